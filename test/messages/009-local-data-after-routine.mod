MODULE t
! @expect-message 5:9: syntax error: expected PROC, FUNC or TRAP after LOCAL: only routine declarations may follow the first routine declaration (§5.1, §9.2); found VAR
  PROC main()
  ENDPROC
  LOCAL VAR num n;
ENDMODULE
