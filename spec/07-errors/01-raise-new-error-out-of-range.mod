MODULE raise_new_error_out_of_range
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description Dialect, R-4.11-handler1: a number outside 1..90 in a RAISE of an error handler is ERR_ILLRAISE, an error of the handler itself: it goes to the system error handler (section 7.1), not to the caller.
! @output p handler
! @exit 1
! @error ERR_ILLRAISE 16:5
  PROC p()
    VAR num zero;
    VAR num x;
    x := 1 / zero;
  ERROR
    TPWrite "p handler";
    RAISE 91;
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "not the handler of main";
    TRYNEXT;
  ENDPROC
ENDMODULE
