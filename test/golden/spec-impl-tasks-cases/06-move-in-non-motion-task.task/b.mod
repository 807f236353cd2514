MODULE move_b
! @task T_B
  CONST robtarget p1 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveL p1, v100, fine, tool0;
  ENDPROC
ENDMODULE
