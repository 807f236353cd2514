MODULE t
! @expect-message 3:16: syntax error: expected '{' for an array parameter, or ',', '|', '\' or ')' after the parameter (§5.2); found ':='
  PROC p(num n := 1)
  ENDPROC
ENDMODULE
