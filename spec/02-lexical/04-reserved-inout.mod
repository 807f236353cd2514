MODULE reserved_inout
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word INOUT cannot be used as an identifier.
  VAR num INOUT;
ENDMODULE
