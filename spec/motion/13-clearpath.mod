MODULE clearpath_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description ClearPath drops what the robot has not done (S-stop): stopped 2 s into a \Conc move towards p2 (at y = -50), the path is cleared, and the next move starts from where the robot stands: back to p1, 200 mm, 2 s.
! @output y -50
! @output end 4000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL \Conc, p2, v100, fine, tool0;
    WaitTime 2;
    StopMove;
    ClearPath;
    StartMove;
    p := CPos(\Tool:=tool0);
    TPWrite "y " \Num:=Round(p.y);
    MoveL p1, v100, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE
