MODULE t
! @expect-message 4:15: syntax error: expected an operand after NOT (§3.1); NOT may only begin an expression: write NOT (NOT ...); comments are list elements only (§2.10); found NOT
  PROC main()
    ok := NOT NOT b;
  ENDPROC
ENDMODULE
