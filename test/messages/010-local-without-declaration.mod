MODULE t
! @expect-message 3:9: syntax error: expected RECORD, ALIAS, VAR, PERS, CONST, PROC, FUNC or TRAP after LOCAL (§2.11, §2.18, §5.1); found the identifier num
  LOCAL num n;
ENDMODULE
