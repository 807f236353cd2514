MODULE type_name_as_data
! @format 2
! @section 13
! @expect semantic-error 8:10
! @description A type name is not a data object: num in an expression is refused at the name.
  VAR num n;
  PROC main()
    n := num;
  ENDPROC
ENDMODULE
