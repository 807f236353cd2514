MODULE t
! @expect-message 6:3: syntax error: expected a statement, ERROR, UNDO or ENDPROC after the backward handler (§5.4); found BACKWARD
  PROC p()
  BACKWARD
    Stop;
  BACKWARD
  ENDPROC
ENDMODULE
