MODULE data_declaration_task_letter_cas
! @section 2.18
! @expect ok
! @description TASK, though not reserved, is a word of the grammar and is read in any letter case.
  task VAR num a;
  Task PERS num b := 1;
ENDMODULE
