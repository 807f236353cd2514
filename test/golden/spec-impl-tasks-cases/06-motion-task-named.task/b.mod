MODULE named_motion_b
! @task T_MOVE
  CONST jointtarget start := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveAbsJ start, v100, fine, tool0;
    TPWrite "T_MOVE moved";
  ENDPROC
ENDMODULE
