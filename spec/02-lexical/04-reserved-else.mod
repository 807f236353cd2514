MODULE reserved_else
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ELSE cannot be used as an identifier.
  VAR num ELSE;
ENDMODULE
