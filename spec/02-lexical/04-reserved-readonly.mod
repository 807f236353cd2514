MODULE reserved_readonly
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word READONLY cannot be used as an identifier.
  VAR num READONLY;
ENDMODULE
