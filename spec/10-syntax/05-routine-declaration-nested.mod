MODULE routine_declaration_nested
! @section 5.1
! @expect syntax-error 6:5
! @description Routine declarations do not nest.
  PROC outer()
    PROC inner()
    ENDPROC
  ENDPROC
ENDMODULE
