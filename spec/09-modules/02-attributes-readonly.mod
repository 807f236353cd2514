MODULE attributes_readonly(NOSTEPIN, READONLY)
! @format 2
! @section 9.2
! @expect ok
! @description READONLY after NOSTEPIN.
  VAR num n;
ENDMODULE
