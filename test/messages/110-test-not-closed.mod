MODULE t
! @expect-message 8:3: syntax error: expected a statement, CASE, DEFAULT or ENDTEST (§4.20); found ENDPROC
! @expect-hint the TEST at line 5 is not closed: ENDTEST is missing before this ENDPROC (§4.20)
  PROC main()
    TEST a
    CASE 1:
      x := 1;
  ENDPROC
ENDMODULE
