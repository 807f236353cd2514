MODULE Right
  PROC main()
    VAR pos p;
    MoveAbsJ [[-30, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v500, fine, tool0;
    TPWrite "right: at -30 degrees";
    ! MOC.cfg puts ROB_2's base frame at x = 1.5 m: its TCP is beyond x = 1000 mm in the world
    p := CPos(\Tool:=tool0);
    TPWrite "right: beyond x 1000 " \Bool:=p.x > 1000;
  ENDPROC
ENDMODULE
