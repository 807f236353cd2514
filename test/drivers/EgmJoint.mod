MODULE EgmJoint
  ! A joint-mode EGM client (issue 18), in our own words: the robot follows the set points of a
  ! sensor on the UdpUc device "EGMSensor" (rapid-sem run --egm-device EGMSensor=127.0.0.1:PORT)
  ! until every axis has been within its convergence criterion for 0.2 s, then reports where it
  ! stands.
  VAR egmident egm_id;
  CONST egm_minmax near := [-0.1, 0.1];

  PROC main()
    VAR jointtarget reached;
    VAR robtarget flange;
    ! A fresh process: resetting one the variable does not hold does nothing.
    EGMReset egm_id;
    EGMGetId egm_id;
    EGMSetupUC ROB_1, egm_id, "default", "EGMSensor" \Joint \CommTimeout:=5;
    EGMActJoint egm_id \J1:=near \J2:=near \J3:=near \J4:=near \J5:=near \J6:=near
      \SampleRate:=4 \MaxPosDeviation:=1000 \MaxSpeedDeviation:=200;
    TPWrite "egm state before the run " \Num:=EGMGetState(egm_id);
    EGMRunJoint egm_id, EGM_STOP_HOLD \J1 \J2 \J3 \J4 \J5 \J6 \CondTime:=0.2 \RampInTime:=0.05;
    TPWrite "egm state after the run " \Num:=EGMGetState(egm_id);
    reached := CJointT();
    TPWrite "joints " + NumToStr(reached.robax.rax_1, 2) + " " + NumToStr(reached.robax.rax_2, 2) + " "
      + NumToStr(reached.robax.rax_3, 2) + " " + NumToStr(reached.robax.rax_4, 2) + " "
      + NumToStr(reached.robax.rax_5, 2) + " " + NumToStr(reached.robax.rax_6, 2);
    flange := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "flange " + NumToStr(flange.trans.x, 2) + " " + NumToStr(flange.trans.y, 2) + " "
      + NumToStr(flange.trans.z, 2);
    EGMReset egm_id;
    TPWrite "egm state after the reset " \Num:=EGMGetState(egm_id);
  ERROR
    IF ERRNO = ERR_UDPUC_COMM THEN
      TPWrite "communication timeout";
      RETURN;
    ELSEIF ERRNO = ERR_COLL_STOP THEN
      ! A collision stops the robot during the run (the stimulus's "at TIME collision"): the
      ! handler keeps the run's program point for RETRY, so the process still runs until
      ! EGMStop.
      TPWrite "collision, egm state " \Num:=EGMGetState(egm_id);
      EGMStop egm_id, EGM_STOP_HOLD;
      TPWrite "after EGMStop " \Num:=EGMGetState(egm_id);
      RETURN;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
