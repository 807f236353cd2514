MODULE reserved_error
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ERROR cannot be used as an identifier.
  VAR num ERROR;
ENDMODULE
