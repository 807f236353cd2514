MODULE conc_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description \Conc: the program pointer leaves the move when its motion begins (PP-conc), here at once; WaitTime \InPos waits until the robot stands still, then its time (0.5 s): 5 + 0.5.
! @output after MoveL 0
! @output in position 5500
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL \Conc, p2, v100, fine, tool0;
    TPWrite "after MoveL " \Num:=Round(1000 * ClkRead(clk));
    WaitTime \InPos, 0.5;
    TPWrite "in position " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE
