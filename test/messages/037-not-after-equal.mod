MODULE t
! @expect-message 4:15: syntax error: expected a simple expression after the comparison operator (§3.1); NOT may only begin an expression: write (NOT ...); comments are list elements only (§2.10); found NOT
  PROC main()
    ok := a = NOT b;
  ENDPROC
ENDMODULE
