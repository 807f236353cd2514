MODULE reserved_from
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word FROM cannot be used as an identifier.
  VAR num FROM;
ENDMODULE
