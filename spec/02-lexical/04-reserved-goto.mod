MODULE reserved_goto
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word GOTO cannot be used as an identifier.
  VAR num GOTO;
ENDMODULE
