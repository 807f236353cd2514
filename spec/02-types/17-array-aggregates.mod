MODULE array_aggregates
! @format 2
! @section 2.17
! @section 3.10
! @expect ok
! @description Array aggregates: section 2.23's grid, and assignments of aggregates to one- and two-dimensional arrays.
  VAR num a{3};
  VAR num grid{2, 2} := [[0, 0], [0, 0]];
  VAR pos corners{2};
  PROC main()
    a := [1, 2, 3];
    grid := [[1, 2], [3, 4]];
    corners := [[0, 0, 0], [1, 1, 1]];
  ENDPROC
ENDMODULE
