MODULE reserved_backward
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word BACKWARD cannot be used as an identifier.
  VAR num BACKWARD;
ENDMODULE
