MODULE reserved_func
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word FUNC cannot be used as an identifier.
  VAR num FUNC;
ENDMODULE
