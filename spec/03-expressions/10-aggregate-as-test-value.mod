MODULE aggregate_as_test_value
! @format 2
! @section 3.10
! @section 4.20
! @expect ok
! @description The test expression's type determines the type of aggregate test values.
  VAR pos p;
  VAR num n;
  PROC main()
    TEST p
    CASE [0, 0, 0]:
      n := 0;
    CASE [1, 0, 0], [0, 1, 0]:
      n := 1;
    ENDTEST
  ENDPROC
ENDMODULE
