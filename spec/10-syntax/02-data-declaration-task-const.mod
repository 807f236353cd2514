MODULE data_declaration_task_const
! @section 2.18
! @expect syntax-error 5:8
! @description TASK applies to variable and persistent declarations only.
  TASK CONST num c := 1;
ENDMODULE
