MODULE t
! @expect-message 4:18: syntax error: expected ',' or the end of the argument list: '?' is followed by a parameter, not an expression (§3.11, §4.6); found '+'
  PROC main()
    Print \x ? a + 1;
  ENDPROC
ENDMODULE
