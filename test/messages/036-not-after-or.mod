MODULE t
! @expect-message 4:16: syntax error: expected a logical term after OR or XOR (§3.1); NOT may only begin an expression: write OR (NOT ...); comments are list elements only (§2.10); found NOT
  PROC main()
    ok := a OR NOT b;
  ENDPROC
ENDMODULE
