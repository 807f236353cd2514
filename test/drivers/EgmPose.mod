MODULE EgmPose
  ! A pose-mode EGM client (issue 18), in our own words: the TCP of a tool follows the Cartesian
  ! set points of a sensor on the UdpUc device "EGMSensor", given in the frame of a work object
  ! (EGM_FRAME_WOBJ), until every direction has been within its convergence criterion for
  ! 0.2 s; then it reports where CRobT finds the TCP in that work object.
  VAR egmident egm_id;
  CONST egm_minmax lin := [-0.1, 0.1];
  CONST egm_minmax rot := [-0.1, 0.1];
  PERS tooldata probe := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata table := [FALSE, TRUE, "", [[100, 50, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  CONST jointtarget start := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST pose frame := [[0, 0, 0], [1, 0, 0, 0]];

  PROC main()
    VAR robtarget reached;
    MoveAbsJ start, v1000, fine, tool0;
    EGMReset egm_id;
    EGMGetId egm_id;
    EGMSetupUC ROB_1, egm_id, "default", "EGMSensor" \Pose \CommTimeout:=5;
    EGMActPose egm_id \Tool:=probe \WObj:=table \TLoad:=load0, frame, EGM_FRAME_WOBJ, frame, EGM_FRAME_WOBJ
      \x:=lin \y:=lin \z:=lin \rx:=rot \ry:=rot \rz:=rot \SampleRate:=4 \MaxPosDeviation:=1000
      \MaxSpeedDeviation:=100;
    TPWrite "egm state before the run " \Num:=EGMGetState(egm_id);
    EGMRunPose egm_id, EGM_STOP_HOLD \x \y \z \Rx \Ry \Rz \CondTime:=0.2 \RampInTime:=0.05;
    TPWrite "egm state after the run " \Num:=EGMGetState(egm_id);
    reached := CRobT(\Tool:=probe \WObj:=table);
    TPWrite "tcp " + NumToStr(reached.trans.x, 1) + " " + NumToStr(reached.trans.y, 1) + " "
      + NumToStr(reached.trans.z, 1);
    TPWrite "orient " + NumToStr(reached.rot.q1, 3) + " " + NumToStr(reached.rot.q2, 3) + " "
      + NumToStr(reached.rot.q3, 3) + " " + NumToStr(reached.rot.q4, 3);
    EGMReset egm_id;
  ERROR
    IF ERRNO = ERR_UDPUC_COMM THEN
      TPWrite "communication timeout";
      RETURN;
    ELSEIF ERRNO = ERR_ROBLIMIT THEN
      TPWrite "out of reach";
      RETURN;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
