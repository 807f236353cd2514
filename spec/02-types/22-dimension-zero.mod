MODULE dimension_zero
! @format 2
! @section 2.22
! @expect semantic-error 6:16
! @description A dimension must be an integer greater than 0; refused at the dimension 0.
  VAR num none{0};
ENDMODULE
