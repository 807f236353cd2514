MODULE error_number_element
! @section 7.2
! @expect syntax-error 6:11
! @description An error number of a recovery point is an entire data object, not an array element.
  PROC p()
  ERROR (a{1})
  ENDPROC
ENDMODULE
