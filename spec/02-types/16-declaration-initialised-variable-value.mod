MODULE declaration_initialised_variable
! @format 2
! @section 2.16
! @section 2.22
! @expect ok
! @description Table of section 2.16, row variable with initialisation, column value: legal.
  VAR num n := 1;
  VAR orient o := [1, 0, 0, 0];
  VAR string s := "x";
ENDMODULE
