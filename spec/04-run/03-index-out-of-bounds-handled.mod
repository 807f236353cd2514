MODULE index_out_of_bounds_handled
! @format 3
! @section 3.6
! @section 7.1
! @expect ok
! @description ERR_OUTOFBND is an ordinary execution error: the routine's error handler sees it in ERRNO and TRYNEXT continues after the failing assignment.
! @output outofbnd=TRUE
! @output x=0
! @exit 0
  VAR num a{3} := [1, 2, 3];
  PROC main()
    VAR num i := 7;
    VAR num x;
    x := a{i};
    TPWrite "x=" \Num:=x;
  ERROR
    TPWrite "outofbnd=" \Bool:=ERRNO = ERR_OUTOFBND;
    TRYNEXT;
  ENDPROC
ENDMODULE
