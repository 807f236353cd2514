MODULE t
! @expect-message 4:10: syntax error: expected an error number, a num literal or a name, after '(' (§7.2); found '-'
  PROC p()
  ERROR (-1)
    RETRY;
  ENDPROC
ENDMODULE
