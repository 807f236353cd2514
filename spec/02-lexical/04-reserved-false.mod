MODULE reserved_false
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word FALSE cannot be used as an identifier.
  VAR num FALSE;
ENDMODULE
