MODULE reserved_var
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word VAR cannot be used as an identifier.
  VAR num VAR;
ENDMODULE
