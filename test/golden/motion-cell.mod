MODULE motion_cell
  ! A small cell for the golden tests of the motion output: a fly-by point, a trap on an input
  ! during a move, an output set at the middle of a corner path.
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum part;
  TRAP part_seen
    VAR pos p;
    p := CPos(\Tool:=tool0);
    TPWrite "part seen at y " \Num:=Round(p.y);
  ENDTRAP
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    CONNECT part WITH part_seen;
    ISignalDI di_part, 1, part;
    MoveLDO p2, v200, z20, tool0, do_glue, 1;
    MoveL Offs(p2, 0, 0, 100), v200, fine, tool0;
    TPWrite "done";
    IDelete part;
  ENDPROC
ENDMODULE
