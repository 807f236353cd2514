MODULE routine_declaration_task
! @section 5.1
! @section 2.18
! @expect syntax-error 6:8
! @description Only LOCAL may precede a routine declaration; TASK belongs to data declarations.
  TASK PROC p()
  ENDPROC
ENDMODULE
