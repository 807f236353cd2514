MODULE t
! @expect-message 5:3: syntax error: expected an operator, or what follows the expression such as ';' (§3.1, §4.2); comments are list elements only (§2.10); found ENDPROC
  PROC main()
    RAISE ERR_X
  ENDPROC
ENDMODULE
