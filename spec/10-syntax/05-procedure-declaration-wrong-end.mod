MODULE procedure_declaration_wrong_end
! @section 5.4
! @expect syntax-error 6:3
! @description A procedure declaration is closed by ENDPROC.
  PROC p()
  ENDFUNC
ENDMODULE
