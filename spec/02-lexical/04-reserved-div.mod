MODULE reserved_div
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word DIV cannot be used as an identifier.
  VAR num DIV;
ENDMODULE
