MODULE egm_comm_timeout
! @format 3
! @section 13
! @expect ok
! @egm-device EGMSensor=127.0.0.1:9
! @statement-time 0
! @description EGMRunJoint with no sensor answering (ABB's EGMSetupUC \CommTimeout, EGMRunJoint; doc/rulings.md R-13-egm4, R-13-egm5): the robot sends its feedback every 4 ms of virtual time, no message comes, and after \CommTimeout (0.2 s) of virtual time the instruction ends with ERR_UDPUC_COMM; the process is connected again, and the robot has not moved.
! @output timeout ERR_UDPUC_COMM after 0.200 s
! @output state 1
! @output joint 1 0
  VAR egmident id;
  VAR clock c;
  PROC main()
    VAR jointtarget j;
    EGMGetId id;
    EGMSetupUC ROB_1, id, "default", "EGMSensor" \Joint \CommTimeout:=0.2;
    EGMActJoint id \MaxSpeedDeviation:=100;
    ClkStart c;
    EGMRunJoint id, EGM_STOP_HOLD \J1 \J2 \J3 \J4 \J5 \J6 \CondTime:=1;
    TPWrite "not here";
  ERROR
    IF ERRNO = ERR_UDPUC_COMM THEN
      TPWrite "timeout ERR_UDPUC_COMM after " + NumToStr(ClkRead(c), 3) + " s";
      TPWrite "state " \Num:=EGMGetState(id);
      j := CJointT();
      TPWrite "joint 1 " \Num:=j.robax.rax_1;
      RETURN;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
