MODULE weld
! @format 2
! @section 9.2
! @section 5.3
! @expect semantic-error 7:8
! @description A global routine and a module may not share a name; refused at the routine's name.
  PROC weld()
  ENDPROC
ENDMODULE
