MODULE reference_argument_semi_value_in
! @format 2
! @section 2.16
! @section 5.2
! @section 2.17
! @expect ok
! @description Ruling: the argument of an in parameter is an expression, evaluated in value context, so a semi-value object passes its associated num value (TPWrite \Num, a user in parameter).
  VAR signaldi sig1;
  PROC show(num n)
  ENDPROC
  PROC main()
    show sig1;
    TPWrite "input" \Num:=sig1;
  ENDPROC
ENDMODULE
