MODULE t
! @expect-message 7:5: syntax error: expected a statement, or BACKWARD, ERROR, UNDO or the routine's ENDPROC, ENDFUNC or ENDTRAP (§5.4-§5.6); data declarations go before the first statement (§5.4); found ELSE
! @expect-hint the IF at line 5 has no THEN after its condition (at 5:8), so it was read as a compact IF (§4.17), which takes one simple statement and no ENDIF: write THEN after the condition (§4.16)
  PROC main()
    IF a > 1
      x := 1;
    ELSE
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
