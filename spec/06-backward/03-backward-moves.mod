MODULE backward_moves
! @format 3
! @section 6.3
! @expect ok
! @description Move instructions in a BACKWARD handler run as moves, in the mirrored order of the forward ones (section 6.3); forward, only the body's moves run; backward, the handler's moves retrace the forward ones, newest first (R-6.3-m): MoveL p2 takes the robot from p2 back to p1, MoveJ p1 from p1 back to where it stood before the forward MoveJ, the IRB 120's home (all axes 0, the flange at y 0). The backward run is pinned by test/golden/debug-back-moves.cmd.
! @exit 0
! @output at y 250
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR pos here;
  PROC MoveTo()
    MoveJ p1, v1000, fine, tool0;
    MoveL p2, v500, fine, tool0;
  BACKWARD
    MoveL p2, v500, fine, tool0;
    MoveJ p1, v1000, fine, tool0;
    here := CPos(\Tool:=tool0);
    TPWrite "back at y " \Num:=here.y;
  ENDPROC
  PROC main()
    MoveTo;
    here := CPos(\Tool:=tool0);
    TPWrite "at y " \Num:=here.y;
  ENDPROC
ENDMODULE
