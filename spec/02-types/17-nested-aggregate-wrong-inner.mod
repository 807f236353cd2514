MODULE nested_aggregate_wrong_inner
! @format 2
! @section 2.17
! @section 3.10
! @expect semantic-error 9:22
! @description The second row of a 2 x 2 aggregate has three members; refused at that row, the inner aggregate of the wrong size.
  VAR num grid{2, 2};
  PROC main()
    grid := [[0, 0], [0, 0, 0]];
  ENDPROC
ENDMODULE
