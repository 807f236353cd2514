MODULE aggregate_as_test_expression
! @format 2
! @section 3.10
! @section 4.20
! @expect semantic-error 9:10
! @description An aggregate as test expression has no context to determine its type; refused at the aggregate.
  VAR num n;
  PROC main()
    TEST [1, 2]
    DEFAULT:
      n := 0;
    ENDTEST
  ENDPROC
ENDMODULE
