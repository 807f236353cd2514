MODULE flyby_program_pointer
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description A fly-by point: the program pointer leaves the move 0.1 s (the look-ahead horizon) before the robot enters the zone (PP-flyby). z10 on a 500 mm MoveL at v100: the corner begins 10 mm = 0.1 s before the point, so the statements after the move run at 5 - 0.1 - 0.1 = 4.8 s, ahead of the robot; CPos there reads where the robot is then (y = -250 + 480). The corner takes no time away (Z-corner): the next 100 mm at v100 ends at 6 s.
! @output ahead 4800
! @output y 230
! @output end 6000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL p2, v100, z10, tool0;
    TPWrite "ahead " \Num:=Round(1000 * ClkRead(clk));
    p := CPos(\Tool:=tool0);
    TPWrite "y " \Num:=Round(p.y);
    MoveL Offs(p2, 0, 0, 100), v100, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE
