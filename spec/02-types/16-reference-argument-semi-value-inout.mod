MODULE reference_argument_semi_value
! @format 2
! @section 2.16
! @section 11
! @expect semantic-error 10:17
! @description Table of section 2.16, row argument, column semi-value: IsPers's parameter is inout, so refused at the argument.
  VAR signaldi sig1;
  VAR bool b;
  PROC main()
    b := IsPers(sig1);
  ENDPROC
ENDMODULE
