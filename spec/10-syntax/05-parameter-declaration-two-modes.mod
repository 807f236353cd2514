MODULE parameter_declaration_two_modes
! @section 5.2
! @expect syntax-error 5:14
! @description A parameter declaration has at most one access mode.
  PROC p(VAR PERS num a)
  ENDPROC
ENDMODULE
