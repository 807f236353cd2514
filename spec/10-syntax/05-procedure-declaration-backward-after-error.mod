MODULE procedure_declaration_backward_a
! @section 5.4
! @expect syntax-error 7:3
! @description BACKWARD comes before ERROR.
  PROC p()
  ERROR
  BACKWARD
  ENDPROC
ENDMODULE
