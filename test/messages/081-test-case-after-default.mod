MODULE t
! @expect-message 6:5: syntax error: expected a statement or ENDTEST after DEFAULT: the CASE parts come before DEFAULT (§4.20); found CASE
  PROC main()
    TEST mode
    DEFAULT:
    CASE 1:
    ENDTEST
  ENDPROC
ENDMODULE
