MODULE rulings_num_overflow
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description R-3.12-c: a num product beyond the largest single (about 3.4E38) is the execution error ERR_OVERFLOW, not an infinity; the task stops at the assignment.
! @output 1E37 * 10 is a num
! @exit 1
! @error ERR_OVERFLOW 15:5
  PROC main()
    VAR num a := 1E37;
    VAR num x;
    x := a * 10;
    TPWrite "1E37 * 10 is a num";
    x := a * 100;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
