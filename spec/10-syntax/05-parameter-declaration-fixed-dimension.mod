MODULE parameter_declaration_fixed_dime
! @section 5.2
! @expect syntax-error 5:16
! @description An array parameter has conformant dimensions '*' (or <DIM>), not fixed ones.
  PROC p(num a{3})
  ENDPROC
ENDMODULE
