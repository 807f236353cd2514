MODULE manual_example
! @format 2
! @section 2.24
! @expect ok
! @description The constant array of section 2.24.
  CONST pos seq{3} := [[614, 778, 1020], [914, 998, 1021], [814, 998, 1022]];
ENDMODULE
