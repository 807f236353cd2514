MODULE reserved_endtest
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDTEST cannot be used as an identifier.
  VAR num ENDTEST;
ENDMODULE
