MODULE egm_pose_timeout
! @format 3
! @section 13
! @expect ok
! @egm-device EGMSensor=127.0.0.1:9
! @statement-time 0
! @description EGMRunPose with no sensor answering (ABB's EGMSetupUC \CommTimeout, EGMRunPose; doc/rulings.md R-13-egm4, R-13-egm6): the robot sends its feedback every 4 ms of virtual time, no pose set point comes, and after \CommTimeout (0.2 s) the instruction ends with ERR_UDPUC_COMM; the process is connected again and the TCP has not moved.
! @output timeout ERR_UDPUC_COMM after 0.200 s
! @output state 1
! @output unmoved TRUE
  VAR egmident id;
  VAR clock c;
  VAR robtarget before;
  PROC main()
    before := CRobT(\Tool:=tool0 \WObj:=wobj0);
    EGMGetId id;
    EGMSetupUC ROB_1, id, "default", "EGMSensor" \Pose \CommTimeout:=0.2;
    EGMActPose id \Tool:=tool0, [[0, 0, 0], [1, 0, 0, 0]], EGM_FRAME_BASE, [[0, 0, 0], [1, 0, 0, 0]], EGM_FRAME_BASE
      \MaxSpeedDeviation:=100;
    ClkStart c;
    EGMRunPose id, EGM_STOP_HOLD \x \y \z \CondTime:=1 \Offset:=[[0, 0, 10], [1, 0, 0, 0]] \PosCorrGain:=0.5;
    TPWrite "not here";
  ERROR
    IF ERRNO = ERR_UDPUC_COMM THEN
      TPWrite "timeout ERR_UDPUC_COMM after " + NumToStr(ClkRead(c), 3) + " s";
      TPWrite "state " \Num:=EGMGetState(id);
      TPWrite "unmoved " \Bool:=Distance(CPos(\Tool:=tool0 \WObj:=wobj0), before.trans) < 0.001;
      RETURN;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
