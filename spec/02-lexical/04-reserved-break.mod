MODULE reserved_break
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word BREAK cannot be used as an identifier.
  VAR num BREAK;
ENDMODULE
