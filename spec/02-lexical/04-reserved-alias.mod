MODULE reserved_alias
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ALIAS cannot be used as an identifier.
  VAR num ALIAS;
ENDMODULE
