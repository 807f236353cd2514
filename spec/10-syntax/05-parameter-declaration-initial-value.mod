MODULE parameter_declaration_initial_va
! @section 5.2
! @expect syntax-error 5:16
! @description A parameter declaration has no default value.
  PROC p(num a := 1)
  ENDPROC
ENDMODULE
