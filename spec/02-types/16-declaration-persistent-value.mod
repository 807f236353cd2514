MODULE declaration_persistent_value
! @format 2
! @section 2.16
! @section 2.23
! @expect ok
! @description Table of section 2.16, row persistent, column value: legal.
  PERS num n := 1;
  PERS pos p := [1, 2, 3];
  PERS bool b;
ENDMODULE
