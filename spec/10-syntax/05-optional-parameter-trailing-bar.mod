MODULE optional_parameter_trailing_bar
! @section 5.2
! @expect syntax-error 5:19
! @description Each '|' is followed by a parameter declaration or <ALT>.
  PROC p(\num a | )
  ENDPROC
ENDMODULE
