MODULE t
! @expect-message 4:11: syntax error: expected VAR, PERS or CONST after LOCAL (§2.18); found the identifier num
  PROC p()
    LOCAL num n;
  ENDPROC
ENDMODULE
