MODULE trap_error_stops_task
! @format 3
! @section 8
! @section 7.1
! @expect ok
! @statement-time 0
! @description An error in a trap without an error handler, with no error recovery point for it at normal level, goes to the system error handler (doc/rulings.md R-8-e): it is not raised at the interrupted statement, and main's ordinary handler does not see it.
! @output in trap
! @exit 1
! @error ERR_DIVZERO 16:5
  VAR intnum t;
  VAR num zero := 0;
  VAR num x;
  TRAP bad
    TPWrite "in trap";
    x := 1 / zero;
    TPWrite "not reached";
  ENDTRAP
  PROC main()
    CONNECT t WITH bad;
    ITimer \Single, 0.1, t;
    WaitTime 1;
    TPWrite "not reached";
  ERROR
    TPWrite "wrong: main's handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
