MODULE reserved_exit
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word EXIT cannot be used as an identifier.
  VAR num EXIT;
ENDMODULE
