MODULE data_name_as_type
! @format 2
! @section 13
! @expect semantic-error 7:7
! @description A data object is not a type: declaring a variable of type counter is refused at the type name.
  VAR num counter;
  VAR counter c2;
ENDMODULE
