MODULE reserved_nostepin
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word NOSTEPIN cannot be used as an identifier.
  VAR num NOSTEPIN;
ENDMODULE
