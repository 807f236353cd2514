MODULE test_statement_default_first
! @section 4.20
! @expect syntax-error 10:5
! @description CASE clauses come before the DEFAULT clause.
  VAR num x;
  PROC main()
    TEST x
    DEFAULT:
      x := 0;
    CASE 1:
      x := 1;
    ENDTEST
  ENDPROC
ENDMODULE
