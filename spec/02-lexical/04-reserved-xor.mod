MODULE reserved_xor
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word XOR cannot be used as an identifier.
  VAR num XOR;
ENDMODULE
