MODULE builtin_function_argument_type
! @format 2
! @section 3.11
! @section 11
! @expect semantic-error 10:21
! @description Dim's dimno parameter is a num; a string is refused at the argument.
  VAR num table{4};
  VAR num n;
  PROC main()
    n := Dim(table, "1");
  ENDPROC
ENDMODULE
