MODULE t
! @expect-message 4:14: syntax error: expected an operand after * / DIV MOD (§3.1); a sign may only begin a simple expression: write * (-x); comments are list elements only (§2.10); found '-'
  PROC main()
    x := y * -1;
  ENDPROC
ENDMODULE
