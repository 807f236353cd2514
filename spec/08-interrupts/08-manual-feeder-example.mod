MODULE feeder_example
! @format 3
! @section 8
! @expect ok
! @io io/feeder.io
! @statement-time 0
! @description Chapter 8's trap example as printed (软中断程序), with open_valve and close_valve that write a line, and a wait in main so that the interrupts come: two interrupt numbers connected to one trap, which tells them apart by INTNO in a TEST; each rising edge of sig1 (empty) and sig3 (full) runs ftrap once.
! @output close
! @output open
! @output close
LOCAL VAR intnum empty;
LOCAL VAR intnum full;
PROC main()
  ! Connect feeder interrupts
 CONNECT empty WITH ftrap;
 CONNECT full WITH ftrap;
  ! define feeder interrupts
  ISignalDI sig1, high, empty;
 ISignalDI sig3, high, full;
 WaitTime 6;
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
PROC open_valve()
  TPWrite "open";
ENDPROC
PROC close_valve()
  TPWrite "close";
ENDPROC
ENDMODULE
