MODULE initialiser_array_wrong_length
! @format 2
! @section 2.22
! @section 2.17
! @expect semantic-error 7:24
! @description The initialiser of an array of 10 elements has 9; refused at the aggregate.
  VAR num maxno{10} := [1, 2, 3, 9, 8, 7, 6, 5, 4];
ENDMODULE
