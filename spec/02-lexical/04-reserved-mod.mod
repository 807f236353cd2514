MODULE reserved_mod
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word MOD cannot be used as an identifier.
  VAR num MOD;
ENDMODULE
