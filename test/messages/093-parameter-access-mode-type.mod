MODULE t
! @expect-message 3:13: syntax error: expected a data type after the access mode (§5.2); found ')'
  PROC p(VAR)
  ENDPROC
ENDMODULE
