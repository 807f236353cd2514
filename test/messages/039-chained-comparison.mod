MODULE t
! @expect-message 4:17: syntax error: a relation holds at most one comparison operator (§3.1): join the comparisons with AND or OR, or use parentheses; found '<'
  PROC main()
    ok := 0 < x < 10;
  ENDPROC
ENDMODULE
