MODULE switch_not_optional
! @format 2
! @section 5.2
! @expect semantic-error 6:20
! @description The type switch may only be given to optional parameters; a required switch is refused at the parameter's name.
  PROC glue(switch on, pos target)
  ENDPROC
ENDMODULE
