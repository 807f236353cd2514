MODULE attribute_twice(SYSMODULE, SYSMODULE)
! @format 2
! @section 9.2
! @expect semantic-error 1:35
! @description An attribute may not be specified more than once; the repetition is refused.
  VAR num n;
ENDMODULE
