MODULE reserved_true
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word TRUE cannot be used as an identifier.
  VAR num TRUE;
ENDMODULE
