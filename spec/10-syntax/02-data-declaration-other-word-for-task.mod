MODULE data_declaration_other_word_for_
! @section 2.18
! @expect syntax-error 5:3
! @description Only the word TASK may stand before VAR or PERS besides LOCAL; TASKS is another identifier.
  TASKS VAR num c;
ENDMODULE
