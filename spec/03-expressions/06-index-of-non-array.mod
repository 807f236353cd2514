MODULE index_of_non_array
! @format 2
! @section 3.6
! @expect semantic-error 8:5
! @description Only arrays have elements; an index on a scalar is refused at its name.
  VAR num n;
  PROC main()
    n{1} := 0;
  ENDPROC
ENDMODULE
