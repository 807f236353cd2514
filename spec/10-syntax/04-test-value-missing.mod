MODULE test_value_missing
! @section 4.20
! @expect syntax-error 8:10
! @description CASE is followed by at least one test value.
  VAR num x;
  PROC main()
    TEST x
    CASE :
      x := 1;
    ENDTEST
  ENDPROC
ENDMODULE
