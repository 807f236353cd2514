MODULE t
! @expect-message 3:8: syntax error: expected the procedure's name after PROC (§5.4); found '('
  PROC ()
  ENDPROC
ENDMODULE
