MODULE t
! @expect-message 6:3: syntax error: expected a statement, ERROR, UNDO or ENDTRAP in the trap routine (§5.6); found ENDPROC
! @expect-hint ENDPROC closes no open construct here; the TRAP t at line 4 is closed by ENDTRAP (§5.6)
  TRAP t
    Stop;
  ENDPROC
ENDMODULE
