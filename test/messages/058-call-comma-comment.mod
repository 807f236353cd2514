MODULE t
! @expect-message 4:15: syntax error: expected an argument after ',' (§4.6); comments are list elements only (§2.10); found a comment
  PROC main()
    MoveL p1, ! target
      v100, z10, tool0;
  ENDPROC
ENDMODULE
