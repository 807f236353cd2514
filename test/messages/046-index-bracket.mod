MODULE t
! @expect-message 4:13: syntax error: expected an operator, ',' or '}' in the index list (§3.6); found ']'
  PROC main()
    x := a{1];
  ENDPROC
ENDMODULE
