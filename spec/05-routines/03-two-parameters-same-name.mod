MODULE two_parameters_same_name
! @format 2
! @section 5.3
! @section 2.20
! @expect semantic-error 7:43
! @description Two parameters of one routine are two routine data objects with the same name; the second is refused at its name.
  PROC move_to(num speed, pos target, num speed)
  ENDPROC
ENDMODULE
