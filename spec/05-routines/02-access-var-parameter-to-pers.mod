MODULE access_var_parameter_to_pers
! @format 2
! @section 5.2
! @expect semantic-error 7:15
! @description Table of section 5.2, row parameter var, column pers: illegal; refused at the argument.
  PROC pass(VAR num x)
    take_pers x;
  ENDPROC

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE
