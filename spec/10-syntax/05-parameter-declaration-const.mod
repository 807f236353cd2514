MODULE parameter_declaration_const
! @section 5.2
! @expect syntax-error 5:10
! @description The access modes are VAR, PERS and INOUT: CONST is not one.
  PROC p(CONST num a)
  ENDPROC
ENDMODULE
