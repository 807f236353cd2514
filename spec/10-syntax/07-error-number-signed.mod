MODULE error_number_signed
! @section 7.2
! @expect syntax-error 6:10
! @description An error number of a recovery point is a num literal or an entire data object: a signed number is not.
  PROC p()
  ERROR (-1)
  ENDPROC
ENDMODULE
