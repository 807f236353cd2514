MODULE reserved_step
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word STEP cannot be used as an identifier.
  VAR num STEP;
ENDMODULE
