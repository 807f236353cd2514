MODULE optional_parameter_bare_backslas
! @section 5.2
! @expect syntax-error 5:18
! @description '\' is followed by a parameter declaration or <ALT>.
  PROC p(num a, \)
  ENDPROC
ENDMODULE
