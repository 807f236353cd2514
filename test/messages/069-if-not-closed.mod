MODULE t
! @expect-message 7:3: syntax error: expected a statement, ELSEIF, ELSE or ENDIF (§4.16); found ENDPROC
! @expect-hint the IF at line 5 is not closed: ENDIF is missing before this ENDPROC (§4.16)
  PROC main()
    IF ok THEN
      x := 1;
  ENDPROC
ENDMODULE
