MODULE trap_own_handler
! @format 3
! @section 8
! @section 7.1
! @expect ok
! @statement-time 0
! @description A trap may have its own error handler: TRYNEXT goes on in the trap, and after ENDTRAP execution goes on where the interrupt came in.
! @output handled in trap TRUE
! @output trap ends
! @output main goes on
  VAR intnum t;
  VAR num zero := 0;
  VAR num x;
  TRAP careful
    x := 1 / zero;
    TPWrite "trap ends";
  ERROR
    TPWrite "handled in trap " \Bool:=(ERRNO = ERR_DIVZERO);
    TRYNEXT;
  ENDTRAP
  PROC main()
    CONNECT t WITH careful;
    ITimer \Single, 0.1, t;
    WaitTime 1;
    TPWrite "main goes on";
  ENDPROC
ENDMODULE
