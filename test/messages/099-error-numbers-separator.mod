MODULE t
! @expect-message 4:16: syntax error: expected ',' or ')' in the error number list (§7.2); found the identifier ERR_B
  PROC p()
  ERROR (ERR_A ERR_B)
    RETRY;
  ENDPROC
ENDMODULE
