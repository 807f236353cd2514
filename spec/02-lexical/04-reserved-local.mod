MODULE reserved_local
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word LOCAL cannot be used as an identifier.
  VAR num LOCAL;
ENDMODULE
