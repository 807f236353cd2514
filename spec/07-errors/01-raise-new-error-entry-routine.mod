MODULE raise_new_error_entry_routine
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description Dialect, R-4.11-handler1: the entry routine has no caller, so a new error raised in its handler goes to the system error handler, which reports the new error at the RAISE.
! @output main handler
! @exit 1
! @error 9 16:5
  PROC main()
    VAR num zero;
    VAR num x;
    x := 1 / zero;
  ERROR
    TPWrite "main handler";
    RAISE 9;
  ENDPROC
ENDMODULE
