MODULE reserved_for
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word FOR cannot be used as an identifier.
  VAR num FOR;
ENDMODULE
