MODULE variable_definition_two_names
! @section 2.22
! @expect syntax-error 5:12
! @description A variable declaration declares one name.
  VAR num a, b;
ENDMODULE
