MODULE routine_name_as_data
! @format 2
! @section 13
! @expect semantic-error 8:10
! @description A routine is not a data object: a procedure name in an expression is refused at the name.
  VAR num n;
  PROC main()
    n := helper + 1;
  ENDPROC
  PROC helper()
  ENDPROC
ENDMODULE
