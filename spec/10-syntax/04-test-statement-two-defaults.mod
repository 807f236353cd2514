MODULE test_statement_two_defaults
! @section 4.20
! @expect syntax-error 9:5
! @description A TEST statement has at most one DEFAULT clause.
  VAR num x;
  PROC main()
    TEST x
    DEFAULT:
    DEFAULT:
    ENDTEST
  ENDPROC
ENDMODULE
