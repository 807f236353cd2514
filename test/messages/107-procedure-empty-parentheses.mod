MODULE t
! @expect-message 5:10: syntax error: expected an expression after '(' (§3.1); comments are list elements only (§2.10); found ')'
! @expect-hint a procedure call takes its arguments without parentheses (§4.6): write Stop; instead of Stop();
  PROC main()
    Stop();
  ENDPROC
ENDMODULE
