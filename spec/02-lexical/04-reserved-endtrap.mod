MODULE reserved_endtrap
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDTRAP cannot be used as an identifier.
  VAR num ENDTRAP;
ENDMODULE
