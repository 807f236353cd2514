MODULE user_continue_retry_limit
! @format 3
! @section 7.3
! @section 7.1
! @expect ok
! @description RETRY in the user level's handler after RaiseToUser \Continue is the NOSTEPIN routine's own RETRY: it counts against that routine's retry limit (default 4, section 7.1), and the fifth raises ERR_EXCRTYMAX, which the system error handler reports at the user level (doc/rulings.md R-7.3-o, R-7.3-p).
! @output main handler
! @output main handler
! @output main handler
! @output main handler
! @output main handler
! @exit 1
! @error ERR_EXCRTYMAX a.mod:15:5
  PROC main()
    tool;
  ERROR
    TPWrite "main handler";
    RETRY;
  ENDPROC
ENDMODULE
