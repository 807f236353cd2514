MODULE t
! @expect-message 4:14: syntax error: expected a term after + or - (§3.1); a sign may only begin a simple expression: write + (-x); comments are list elements only (§2.10); found a comment
  PROC main()
    x := y + ! half
         z;
  ENDPROC
ENDMODULE
