MODULE t
! @expect-message 4:15: syntax error: no '(' or '[' is open for this bracket to close: expected an operator or the end of the expression (§3.1); found ')'
  PROC main()
    x := y + 1);
  ENDPROC
ENDMODULE
