MODULE procedure_declaration_two_error_
! @section 5.4
! @expect syntax-error 7:3
! @description A procedure has at most one ERROR part.
  PROC p()
  ERROR
  ERROR
  ENDPROC
ENDMODULE
