MODULE parameter_list_trailing_comma
! @section 5.2
! @expect syntax-error 5:17
! @description ',' in a parameter list is followed by a parameter declaration.
  PROC p(num a, )
  ENDPROC
ENDMODULE
