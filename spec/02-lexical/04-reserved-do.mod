MODULE reserved_do
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word DO cannot be used as an identifier.
  VAR num DO;
ENDMODULE
