MODULE reserved_then
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word THEN cannot be used as an identifier.
  VAR num THEN;
ENDMODULE
