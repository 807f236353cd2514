MODULE index_second_dimension
! @format 3
! @section 3.6
! @section 12
! @expect ok
! @description Each index is checked against its own dimension: m{1, 4} of a 3 x 2 matrix is out of bounds in the second dimension (ERR_OUTOFBND), although 4 is within the first.
! @output m{3,2}=6
! @exit 1
! @error ERR_OUTOFBND 14:5
  VAR num m{3, 2} := [[1, 2], [3, 4], [5, 6]];
  PROC main()
    VAR num j := 4;
    TPWrite "m{3,2}=" \Num:=m{3, 2};
    TPWrite "m{1,4}=" \Num:=m{1, j};
  ENDPROC
ENDMODULE
