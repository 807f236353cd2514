MODULE Cell
  VAR num tries := 0;
  CONST jointtarget start_pos := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget far_pos := [[45, 10, 10, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    MoveAbsJ start_pos, v1000, fine, tool0;
    WaitDI diPartReady, 1;
    SetDO doGrip, 1;
    MoveAbsJ far_pos, v200, fine, tool0;
    cell_cycles := cell_cycles + 1;
    cell_done := TRUE;
    TPWrite "cell: cycle done";
    ! NoOfRetry of SYS.cfg (2) bounds the RETRYs of flaky's handler: the third error is
    ! ERR_EXCRTYMAX, which stops the task.
    flaky;
  ENDPROC

  PROC flaky()
    VAR num zero := 0;
    tries := tries + 1;
    tries := tries + 0 / zero;
  ERROR
    RETRY;
  ENDPROC

  PROC startup()
    TPWrite "cell: the power-on routine";
  ENDPROC
ENDMODULE
