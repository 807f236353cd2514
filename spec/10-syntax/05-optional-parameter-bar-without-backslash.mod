MODULE optional_parameter_bar_without_b
! @section 5.2
! @expect syntax-error 5:16
! @description Alternatives separated by '|' belong to an optional parameter declaration, which begins with '\'.
  PROC p(num a | num b)
  ENDPROC
ENDMODULE
