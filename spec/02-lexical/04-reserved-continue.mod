MODULE reserved_continue
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word CONTINUE cannot be used as an identifier.
  VAR num CONTINUE;
ENDMODULE
