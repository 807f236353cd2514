MODULE t
! @expect-message 4:3: syntax error: expected '(' and the parameter list after the procedure's name (§5.4); found ENDPROC
  PROC main
  ENDPROC
ENDMODULE
