MODULE reserved_module
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word MODULE cannot be used as an identifier.
  VAR num MODULE;
ENDMODULE
