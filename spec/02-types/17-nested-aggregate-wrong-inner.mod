MODULE nested_aggregate_wrong_inner
! @format 2
! @section 2.17
! @section 3.10
! @expect semantic-error 9:13
! @description The second row of a 2 x 2 aggregate has three members; refused at the start of the whole aggregate.
  VAR num grid{2, 2};
  PROC main()
    grid := [[0, 0], [0, 0, 0]];
  ENDPROC
ENDMODULE
