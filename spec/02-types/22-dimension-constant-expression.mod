MODULE dimension_constant_expression
! @format 2
! @section 2.22
! @expect ok
! @description Dimensions are constant expressions: constants and operations on them.
  CONST num rows := 14;
  CONST num half := 0.5;
  VAR pos pallet{rows, rows + 4};
  VAR num slots{half * 4};
  PERS num counts{rows DIV 2};
ENDMODULE
