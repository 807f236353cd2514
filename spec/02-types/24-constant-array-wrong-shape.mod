MODULE constant_array_wrong_shape
! @format 2
! @section 2.24
! @section 2.17
! @expect semantic-error 7:23
! @description A constant array {3} initialised with two members; refused at the aggregate.
  CONST pos seq{3} := [[614, 778, 1020], [914, 998, 1021]];
ENDMODULE
