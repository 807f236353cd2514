MODULE absent_optional_parameter_use
! @format 2
! @section 5.2
! @section 12
! @expect ok
! @description Using the value of an absent optional parameter is an execution error (ERR_NOTPRES), not a static one.
  VAR num n;
  PROC scale(num x \num factor)
    n := x * factor;
  ENDPROC
ENDMODULE
