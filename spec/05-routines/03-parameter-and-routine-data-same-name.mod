MODULE parameter_and_routine_data_same
! @format 2
! @section 5.3
! @section 2.20
! @expect semantic-error 8:13
! @description A routine variable with the name of a parameter of the same routine; refused at the variable's name.
  PROC move_to(num speed)
    VAR num speed;
  ENDPROC
ENDMODULE
