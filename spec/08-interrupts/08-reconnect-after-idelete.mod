MODULE reconnect_after_idelete
! @format 3
! @section 4.15
! @section 8
! @expect ok
! @statement-time 0
! @description IDelete frees the interrupt number: the same variable can be connected again without ERR_ALRDYCNT (doc/rulings.md R-8-f), here to another trap.
! @output first
! @output second
  VAR intnum i1;
  TRAP first
    TPWrite "first";
  ENDTRAP
  TRAP second
    TPWrite "second";
  ENDTRAP
  PROC main()
    CONNECT i1 WITH first;
    ITimer \Single, 0.1, i1;
    WaitTime 0.5;
    IDelete i1;
    CONNECT i1 WITH second;
    ITimer \Single, 0.1, i1;
    WaitTime 0.5;
  ENDPROC
ENDMODULE
