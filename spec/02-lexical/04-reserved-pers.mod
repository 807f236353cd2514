MODULE reserved_pers
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word PERS cannot be used as an identifier.
  VAR num PERS;
ENDMODULE
