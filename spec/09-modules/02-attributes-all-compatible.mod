MODULE attributes_all_compatible(SYSMODULE, NOSTEPIN, READONLY)
! @format 2
! @section 9.2
! @expect ok
! @description SYSMODULE, NOSTEPIN and READONLY together, in order.
  VAR num n;
ENDMODULE
