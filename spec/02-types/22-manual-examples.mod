MODULE manual_examples
! @format 2
! @section 2.22
! @expect ok
! @description The variable declarations of section 2.22.
  ! pos (14 x 18) matrix
  VAR pos pallet{14, 18};
  VAR string author_name := "John Smith";
  VAR pos start := [100, 100, 50];
  VAR num maxno{10} := [1, 2, 3, 9, 8, 7, 6, 5, 4, 3];
ENDMODULE
