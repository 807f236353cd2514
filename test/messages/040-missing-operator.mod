MODULE t
! @expect-message 4:12: syntax error: expected an operator, or what follows the expression such as ';' (§3.1, §4.2); comments are list elements only (§2.10); found the numeric literal 2
  PROC main()
    x := y 2;
  ENDPROC
ENDMODULE
