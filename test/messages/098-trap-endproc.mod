MODULE t
! @expect-message 5:3: syntax error: expected a statement, ERROR, UNDO or ENDTRAP in the trap routine (§5.6); found ENDPROC
  TRAP t
    Stop;
  ENDPROC
ENDMODULE
