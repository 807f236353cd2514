MODULE velset_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description VelSet 50, 5000 halves the programmed speeds (T-args): the 500 mm MoveL at v100 takes 10 s; with VelSet 100, 50 the TCP speed is capped at 50 mm/s, 10 s again for the way back; MaxRobSpeed is the IRB 120's 6200 mm/s, and so is vmax's v_tcp (the robot's maximum TCP speed).
! @output t 10000
! @output back 20000
! @output max 6200
! @output vmax 6200
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    VelSet 50, 5000;
    MoveL p2, v100, fine, tool0;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    VelSet 100, 50;
    MoveL p1, v1000, fine, tool0;
    TPWrite "back " \Num:=Round(1000 * ClkRead(clk));
    TPWrite "max " \Num:=MaxRobSpeed();
    TPWrite "vmax " \Num:=vmax.v_tcp;
  ENDPROC
ENDMODULE
