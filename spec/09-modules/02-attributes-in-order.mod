MODULE attributes_in_order(SYSMODULE, NOSTEPIN, VIEWONLY)
! @format 2
! @section 9.2
! @expect ok
! @description Attributes in the order of section 9.2's table, each at most once.
  VAR num n;
ENDMODULE
