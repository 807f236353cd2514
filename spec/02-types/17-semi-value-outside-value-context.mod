MODULE semi_value_outside_value_context
! @format 2
! @section 2.17
! @expect semantic-error 12:13
! @description Rule 3 of section 2.17 holds in value context only: a num variable is not a signaldi for a var parameter; refused at the argument.
  VAR num n;
  VAR signaldi di1;
  PROC wait_on(VAR signaldi s)
  ENDPROC
  PROC main()
    wait_on di1;
    wait_on n;
  ENDPROC
ENDMODULE
