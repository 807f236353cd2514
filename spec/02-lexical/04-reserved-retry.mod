MODULE reserved_retry
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word RETRY cannot be used as an identifier.
  VAR num RETRY;
ENDMODULE
