MODULE example_trap_routine
! @section 8
! @expect ok
! @description The trap routine example of chapter 8, its elision after PROC main() left out.
  LOCAL VAR intnum empty;
  LOCAL VAR intnum full;
  PROC main()
    ! Connect feeder interrupts
    CONNECT empty WITH ftrap;
    CONNECT full WITH ftrap;
    ! define feeder interrupts
    ISignalDI sig1, high, empty;
    ISignalDI sig3, high, full;
  ENDPROC
  TRAP ftrap
    TEST INTNO
    CASE empty:
      open_valve;
    CASE full:
      close_valve;
    ENDTEST
    RETURN;
  ENDTRAP
ENDMODULE
