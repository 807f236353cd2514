MODULE error_number_list_trailing_comma
! @section 7.2
! @expect syntax-error 6:14
! @description Each ',' in an error number list is followed by an error number.
  PROC p()
  ERROR (56, )
  ENDPROC
ENDMODULE
