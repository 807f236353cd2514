MODULE Left
  PROC main()
    MoveAbsJ [[10, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v500, fine, tool0;
    TPWrite "left: at 10 degrees";
  ENDPROC
ENDMODULE
