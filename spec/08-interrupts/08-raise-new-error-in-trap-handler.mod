MODULE raise_new_error_in_trap_handler
! @format 3
! @section 8
! @section 4.11
! @expect ok
! @statement-time 0
! @description Dialect, R-4.11-handler1: a new error raised in the error handler of a trap leaves the trap as RAISE without number would (section 4.11: from a trap to the system error handler, there being no recovery point): the task stops with the new error at the RAISE.
! @output trap handler
! @exit 1
! @error 12 18:5
  VAR intnum t;
  TRAP bad
    VAR num zero;
    VAR num x;
    x := 1 / zero;
  ERROR
    TPWrite "trap handler";
    RAISE 12;
  ENDTRAP
  PROC main()
    CONNECT t WITH bad;
    ITimer \Single, 0.1, t;
    WaitTime 1;
  ENDPROC
ENDMODULE
