MODULE division_by_zero
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description Division by zero with / raises ERR_DIVZERO (section 7.1 names division by zero as an execution error) at the assignment; no handler: the task stops.
! @output before
! @exit 1
! @error ERR_DIVZERO 14:5
  PROC main()
    VAR num d := 0;
    VAR num x;
    TPWrite "before";
    x := 1 / d;
    TPWrite "after";
  ENDPROC
ENDMODULE
