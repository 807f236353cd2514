MODULE t
! @expect-message 4:17: syntax error: expected a relation after AND (§3.1); NOT may only begin an expression: write AND (NOT ...); comments are list elements only (§2.10); found NOT
  PROC main()
    ok := a AND NOT b;
  ENDPROC
ENDMODULE
