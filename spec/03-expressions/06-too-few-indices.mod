MODULE too_few_indices
! @format 2
! @section 3.6
! @expect semantic-error 9:10
! @description A two-dimensional array is indexed with two indices; one index is refused at the array's name.
  VAR num m{2, 3};
  VAR num n;
  PROC main()
    n := m{1};
  ENDPROC
ENDMODULE
