MODULE reserved_default
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word DEFAULT cannot be used as an identifier.
  VAR num DEFAULT;
ENDMODULE
