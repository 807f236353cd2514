MODULE dimension_negative
! @format 2
! @section 2.22
! @expect semantic-error 6:18
! @description A dimension must be an integer greater than 0; refused at the dimension expression -3.
  VAR num few{2, -3};
ENDMODULE
