MODULE t
! @expect-message 4:18: syntax error: expected an operator, ',' or ')' after the function argument (§3.11); found ';'
  PROC main()
    x := Max(a, b;
  ENDPROC
ENDMODULE
