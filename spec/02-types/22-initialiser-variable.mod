MODULE initialiser_variable
! @format 2
! @section 2.22
! @section 3.2
! @expect semantic-error 8:16
! @description A variable is initialised by a constant expression, which may not contain a variable; refused at the variable.
  VAR num a := 1;
  VAR num b := a;
ENDMODULE
