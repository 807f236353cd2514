MODULE declaration_constant_value
! @format 2
! @section 2.16
! @section 2.24
! @expect ok
! @description Table of section 2.16, row constant, column value: legal.
  CONST num c := 1;
  CONST pos p := [1, 2, 3];
  CONST string s := "x";
  CONST bool b := FALSE;
ENDMODULE
