MODULE dimension_variable
! @format 2
! @section 2.22
! @section 3.2
! @expect semantic-error 8:21
! @description A dimension is a constant expression and may not contain a variable; refused at the variable.
  VAR num n := 3;
  VAR num table{2 * n};
ENDMODULE
