MODULE parameter_list_missing_comma
! @section 5.2
! @expect syntax-error 5:16
! @description Required parameter declarations are separated by commas.
  PROC p(num a num b)
  ENDPROC
ENDMODULE
