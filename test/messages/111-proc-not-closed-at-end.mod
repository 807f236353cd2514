MODULE t
! @expect-message 6:1: syntax error: expected a statement, or BACKWARD, ERROR, UNDO or the routine's ENDPROC, ENDFUNC or ENDTRAP (§5.4-§5.6); data declarations go before the first statement (§5.4); found the end of the file
! @expect-hint the PROC main at line 4 is not closed: ENDPROC is missing (§5.4)
  PROC main()
    x := 1;
