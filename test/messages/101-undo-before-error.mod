MODULE t
! @expect-message 6:3: syntax error: expected a statement or ENDPROC after the undo handler; BACKWARD and ERROR come before UNDO (§5.4); found ERROR
  PROC p()
  UNDO
    Stop;
  ERROR
    RETRY;
  ENDPROC
ENDMODULE
