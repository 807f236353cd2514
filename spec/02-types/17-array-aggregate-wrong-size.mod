MODULE array_aggregate_wrong_size
! @format 2
! @section 2.17
! @section 3.10
! @expect semantic-error 9:10
! @description An aggregate of two members for an array of three; refused at the aggregate.
  VAR num a{3};
  PROC main()
    a := [1, 2];
  ENDPROC
ENDMODULE
