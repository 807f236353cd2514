MODULE t
! @expect-message 6:3: syntax error: expected a statement, UNDO or ENDPROC after the error handler; BACKWARD comes before ERROR (§5.4); found BACKWARD
  PROC p()
  ERROR
    RETRY;
  BACKWARD
    Stop;
  ENDPROC
ENDMODULE
