MODULE literal_expression
! @section 3.3
! @expect ok
! @description The example of section 3.3, and a signed literal.
  PERS pos refpnt := [100, 778, 1183];
  PERS num diameter := 24.43;
  PERS num below := -2;
ENDMODULE
