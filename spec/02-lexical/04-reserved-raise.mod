MODULE reserved_raise
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word RAISE cannot be used as an identifier.
  VAR num RAISE;
ENDMODULE
