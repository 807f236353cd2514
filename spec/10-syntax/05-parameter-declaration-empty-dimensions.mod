MODULE parameter_declaration_empty_dime
! @section 5.2
! @expect syntax-error 5:16
! @description An array parameter declares at least one '*'.
  PROC p(num a{})
  ENDPROC
ENDMODULE
