MODULE constant_index_not_integer
! @format 2
! @section 3.2
! @section 3.6
! @expect semantic-error 9:24
! @description An element of a constant array selected by a constant index that is not an integer (§3.6): known to fail before the program runs, at the index.
  CONST num table{3} := [10, 20, 30];
  CONST num half := 1 / 2;
  CONST num x := table{half + 1};
  PROC main()
  ENDPROC
ENDMODULE
