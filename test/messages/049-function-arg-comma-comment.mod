MODULE t
! @expect-message 4:17: syntax error: expected a function argument after ',' (§3.11); comments are list elements only (§2.10); found a comment
  PROC main()
    x := Max(a, ! first
             b);
  ENDPROC
ENDMODULE
