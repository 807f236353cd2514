MODULE parameter_declaration_missing_na
! @section 5.2
! @expect syntax-error 5:13
! @description A parameter declaration names a data type and then the parameter.
  PROC p(num)
  ENDPROC
ENDMODULE
