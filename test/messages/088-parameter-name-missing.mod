MODULE t
! @expect-message 3:13: syntax error: expected the parameter's name after its data type (§5.2); found ')'
  PROC p(num)
  ENDPROC
ENDMODULE
