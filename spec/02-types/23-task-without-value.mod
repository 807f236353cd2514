MODULE task_without_value
! @format 2
! @section 2.23
! @expect semantic-error 6:3
! @description A TASK persistent must be initialised; refused at the declaration's first character.
  TASK PERS num state;
ENDMODULE
