MODULE reserved_trynext
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word TRYNEXT cannot be used as an identifier.
  VAR num TRYNEXT;
ENDMODULE
