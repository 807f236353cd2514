MODULE too_many_indices
! @format 2
! @section 3.6
! @expect semantic-error 8:10
! @description The number of indices must fit the array's declared number of dimensions; the first index too many is refused.
  VAR num a{3};
  PROC main()
    a{1, 2} := 0;
  ENDPROC
ENDMODULE
