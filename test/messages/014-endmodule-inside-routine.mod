MODULE t
! @expect-message 5:1: syntax error: expected a statement, or BACKWARD, ERROR, UNDO or the routine's ENDPROC, ENDFUNC or ENDTRAP (§5.4-§5.6); data declarations go before the first statement (§5.4); found ENDMODULE
  PROC a()
    Stop;
ENDMODULE
