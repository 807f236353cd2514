MODULE reserved_endfunc
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDFUNC cannot be used as an identifier.
  VAR num ENDFUNC;
ENDMODULE
