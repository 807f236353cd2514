MODULE movec_time
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description MoveC: the TCP moves on the circle through the start, CirPoint and ToPoint (G-circle); a half circle of radius 100 mm at v100 is 100 pi mm long and takes pi s (T-cartesian).
! @output t 3142
! @output at 300.0 -50.0 300.0
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget c1 := [[400,-150,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[300,-50,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveC c1, p3, v100, fine, tool0;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    p := CPos(\Tool:=tool0);
    TPWrite "at " + NumToStr(p.x, 1) + " " + NumToStr(p.y, 1) + " " + NumToStr(p.z, 1);
  ENDPROC
ENDMODULE
