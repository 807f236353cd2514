MODULE constant_from_variable
! @format 2
! @section 2.24
! @section 3.2
! @expect semantic-error 8:28
! @description A constant expression may not contain a variable; refused at the variable.
  VAR num radius := 25;
  CONST num area := 3.14 * radius * 2;
ENDMODULE
