MODULE switch_argument_to_value
! @format 2
! @section 5.2
! @section 4.6
! @expect semantic-error 10:10
! @description A switch parameter has an empty domain: it cannot be given to a num parameter; refused at the argument.
  PROC show(num x)
  ENDPROC
  PROC glue(\switch on)
    show on;
  ENDPROC
ENDMODULE
