MODULE t
! @expect-message 6:1: syntax error: expected a statement, or BACKWARD, ERROR, UNDO or the routine's ENDPROC, ENDFUNC or ENDTRAP (§5.4-§5.6); data declarations go before the first statement (§5.4); found ENDMODULE
! @expect-hint the PROC a at line 4 is not closed: ENDPROC is missing before this ENDMODULE (§5.4)
  PROC a()
    Stop;
ENDMODULE
