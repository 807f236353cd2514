MODULE constant_declaration
! @section 2.24
! @expect ok
! @description The constant declarations of sections 2.24 and 3.2.
  CONST pos seq{3} := [[614, 778, 1020], [914, 998, 1021], [814, 998, 1022]];
  CONST num radius := 25;
ENDMODULE
