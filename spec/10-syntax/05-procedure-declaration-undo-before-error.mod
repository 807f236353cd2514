MODULE procedure_declaration_undo_befor
! @section 5.4
! @expect syntax-error 7:3
! @description The parts of a procedure come in the order BACKWARD, ERROR, UNDO.
  PROC p()
  UNDO
  ERROR
  ENDPROC
ENDMODULE
