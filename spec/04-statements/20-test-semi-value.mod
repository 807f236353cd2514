MODULE test_semi_value
! @format 2
! @section 4.20
! @section 2.16
! @expect ok
! @description The test expression may be of a semi-value type; its test values are of the associated type num.
  VAR signaldi di1;
  VAR num n;
  PROC main()
    TEST di1
    CASE 0:
      n := 0;
    CASE 1:
      n := 1;
    ENDTEST
  ENDPROC
ENDMODULE
