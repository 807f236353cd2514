MODULE example_interrupt_fragments
! @section 8
! @expect ok
! @description The fragments of chapter 8 (comments printed on one line with the statement they precede are split).
  VAR intnum full;
  VAR intnum empty;
  PROC main()
    CONNECT full WITH ftrap;
    ! define feeder interrupts
    ISignalDI sig3, high, full;
    ! deactivate empty
    ISleep empty;
    ! activate empty again
    IWatch empty;
    ! delete empty
    IDelete empty;
    ! enable interrupts
    IEnable;
    ! disable interrupts
    IDisable;
  ENDPROC
  TRAP ftrap
  ENDTRAP
ENDMODULE
