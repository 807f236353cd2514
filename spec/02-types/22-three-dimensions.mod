MODULE three_dimensions
! @format 2
! @section 2.22
! @expect ok
! @description Arrays of one, two and three dimensions.
  VAR num line{5};
  VAR num plane{2, 3};
  VAR num cube{2, 2, 2} := [[[1, 2], [3, 4]], [[5, 6], [7, 8]]];
ENDMODULE
