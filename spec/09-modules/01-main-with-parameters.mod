MODULE main_with_parameters
! @format 2
! @section 9.1
! @expect semantic-error 6:8
! @description The entry routine cannot have parameters; main with a parameter is refused at its name.
  PROC main(num n)
  ENDPROC
ENDMODULE
