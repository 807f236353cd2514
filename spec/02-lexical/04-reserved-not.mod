MODULE reserved_not
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word NOT cannot be used as an identifier.
  VAR num NOT;
ENDMODULE
