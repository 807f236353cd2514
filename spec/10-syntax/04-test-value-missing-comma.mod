MODULE test_value_missing_comma
! @section 4.20
! @expect syntax-error 8:12
! @description Test values are separated by ','.
  VAR num x;
  PROC main()
    TEST x
    CASE 1 2:
      x := 1;
    ENDTEST
  ENDPROC
ENDMODULE
