MODULE type_definition_task_record
! @section 2.11
! @section 2.18
! @expect syntax-error 6:8
! @description Only LOCAL may precede a type definition; TASK belongs to data declarations.
  TASK RECORD r
    num a;
  ENDRECORD
ENDMODULE
