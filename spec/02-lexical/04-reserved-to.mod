MODULE reserved_to
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word TO cannot be used as an identifier.
  VAR num TO;
ENDMODULE
