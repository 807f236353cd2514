MODULE reference_argument_semi_value
! @format 2
! @section 2.16
! @section 5.2
! @expect semantic-error 11:10
! @description Table of section 2.16, row argument, column semi-value: only to var or ref parameters; refused for a pers num parameter at the argument.
  VAR signaldi sig1;
  PROC keep(PERS num n)
  ENDPROC
  PROC main()
    keep sig1;
  ENDPROC
ENDMODULE
