MODULE local_without_value
! @format 2
! @section 2.23
! @expect semantic-error 6:3
! @description A LOCAL persistent must be initialised; refused at the declaration's first character.
  LOCAL PERS num state;
ENDMODULE
