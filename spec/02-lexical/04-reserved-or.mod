MODULE reserved_or
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word OR cannot be used as an identifier.
  VAR num OR;
ENDMODULE
