MODULE test_statement_missing_colon
! @section 4.20
! @expect syntax-error 8:12
! @description CASE <test value> { ',' <test value> } ':': the colon may not be left out.
  VAR num x;
  PROC main()
    TEST x
    CASE 1 x := 1;
    ENDTEST
  ENDPROC
ENDMODULE
