MODULE index_out_of_bounds
! @format 3
! @section 3.6
! @section 12
! @expect ok
! @description Reading element 4 of an array of 3 elements raises ERR_OUTOFBND (chapter 12) at the statement that evaluates it; no handler, so the system error handler stops the task.
! @output before
! @exit 1
! @error ERR_OUTOFBND 15:5
  VAR num a{3} := [1, 2, 3];
  PROC main()
    VAR num i := 4;
    VAR num x;
    TPWrite "before";
    x := a{i};
    TPWrite "after";
  ENDPROC
ENDMODULE
