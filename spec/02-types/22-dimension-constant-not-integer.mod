MODULE dimension_constant_not_integer
! @format 2
! @section 2.22
! @expect semantic-error 7:16
! @description A constant dimension expression whose value is 1.5 is not an integer; refused at the dimension expression.
  CONST num half := 0.5;
  VAR num part{half * 3};
ENDMODULE
