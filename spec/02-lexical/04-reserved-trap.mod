MODULE reserved_trap
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word TRAP cannot be used as an identifier.
  VAR num TRAP;
ENDMODULE
