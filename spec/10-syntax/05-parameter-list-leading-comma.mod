MODULE parameter_list_leading_comma
! @section 5.2
! @expect syntax-error 5:10
! @description A parameter list does not begin with a comma.
  PROC p(, num a)
  ENDPROC
ENDMODULE
