MODULE data_and_routine_one_module
! @format 2
! @section 2.20
! @section 5.3
! @expect semantic-error 8:8
! @description A module data object and a routine of the same module may not share a name; the routine, which comes second, is refused at its name.
  VAR num calibrate;
  PROC calibrate()
  ENDPROC
ENDMODULE
