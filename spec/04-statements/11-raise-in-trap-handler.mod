MODULE raise_in_trap_handler
! @format 2
! @section 4.11
! @section 7.1
! @expect ok
! @description RAISE without a number in a trap's error handler passes the error to the system error handler.
  TRAP on_event
    DebugBreak;
  ERROR
    RAISE;
  ENDTRAP
ENDMODULE
