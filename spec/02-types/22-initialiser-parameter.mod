MODULE initialiser_parameter
! @format 2
! @section 2.22
! @section 3.2
! @section 5.2
! @expect semantic-error 9:18
! @description Ruling: a parameter is a routine data object, not a constant; it may not initialise a routine variable. Refused at the parameter.
  PROC scale(num k)
    VAR num m := k;
  ENDPROC
ENDMODULE
