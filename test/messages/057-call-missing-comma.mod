MODULE t
! @expect-message 4:20: syntax error: expected an operator, or what follows the expression such as ';' (§3.1, §4.2); comments are list elements only (§2.10); found the identifier z10
  PROC main()
    MoveL p1, v100 z10, tool0;
  ENDPROC
ENDMODULE
