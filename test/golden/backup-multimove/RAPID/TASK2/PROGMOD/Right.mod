MODULE Right
  PROC main()
    MoveAbsJ [[-30, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v500, fine, tool0;
    TPWrite "right: at -30 degrees";
  ENDPROC
ENDMODULE
