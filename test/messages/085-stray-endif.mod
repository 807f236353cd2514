MODULE t
! @expect-message 5:5: syntax error: expected a statement, or BACKWARD, ERROR, UNDO or the routine's ENDPROC, ENDFUNC or ENDTRAP (§5.4-§5.6); data declarations go before the first statement (§5.4); found ENDIF
  PROC main()
    IF a > b x := 1;
    ENDIF
  ENDPROC
ENDMODULE
