MODULE undeclared_data
! @format 2
! @section 13
! @expect semantic-error 8:10
! @description A data object that is neither declared, predefined nor installed; refused at its name.
  VAR num n;
  PROC main()
    n := speed_factor * 2;
  ENDPROC
ENDMODULE
