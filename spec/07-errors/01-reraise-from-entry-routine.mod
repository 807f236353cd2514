MODULE reraise_from_entry_routine
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description RAISE; in the entry routine's handler: the top of the call chain is reached, so the system error handler stops the task and reports the error where it occurred, in p (section 7.1).
! @output main handler
! @exit 1
! @error ERR_DIVZERO 13:5
  PROC p()
    VAR num d;
    VAR num x;
    x := 1 / d;
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "main handler";
    RAISE;
  ENDPROC
ENDMODULE
