MODULE alternatives_same_name
! @format 2
! @section 5.3
! @section 2.20
! @expect semantic-error 7:47
! @description Alternatives of an optional parameter are parameters too; two with one name are refused at the second name.
  PROC move_to(pos target \num level | string level)
  ENDPROC
ENDMODULE
