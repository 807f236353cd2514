MODULE motion_end
  ! The task ends while the robot still moves: its motion events follow task-ended (R-4.1-h).
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    MoveL \Conc, p2, v100, z10, tool0;
    TPWrite "program done";
  ENDPROC
ENDMODULE
