MODULE t
! @expect-message 4:8: syntax error: expected a conditional expression after IF (§4.16, §4.17); found THEN
  PROC main()
    IF THEN
    ENDIF
  ENDPROC
ENDMODULE
