MODULE reserved_with
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word WITH cannot be used as an identifier.
  VAR num WITH;
ENDMODULE
