MODULE main_with_optional_parameter
! @format 2
! @section 9.1
! @expect semantic-error 6:8
! @description An optional parameter is a parameter too; refused at main.
  PROC Main(\switch verbose)
  ENDPROC
ENDMODULE
