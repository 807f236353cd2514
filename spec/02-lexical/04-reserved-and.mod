MODULE reserved_and
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word AND cannot be used as an identifier.
  VAR num AND;
ENDMODULE
