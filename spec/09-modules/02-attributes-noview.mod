MODULE attributes_noview(SYSMODULE, NOVIEW)
! @format 2
! @section 9.2
! @expect ok
! @description NOVIEW with SYSMODULE, which it does not exclude.
  VAR num n;
ENDMODULE
