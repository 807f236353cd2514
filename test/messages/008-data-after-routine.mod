MODULE t
! @expect-message 5:3: syntax error: expected a routine declaration or ENDMODULE: type definitions and data declarations come before the routine declarations (§9.2); found VAR
  PROC main()
  ENDPROC
  VAR num n;
ENDMODULE
