MODULE itimer_cyclic
! @format 3
! @section 8
! @section 4.15
! @expect ok
! @statement-time 0
! @description CONNECT binds an interrupt number to a trap; ITimer orders an interrupt every Time seconds (cyclic without \Single); interrupts are served during a wait (chapter 8); after IDelete none comes any more.
! @output ticks 4
! @output after IDelete 4
  VAR intnum t1;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT t1 WITH tick;
    ITimer 0.5, t1;
    WaitTime 2.2;
    TPWrite "ticks " \Num:=n;
    IDelete t1;
    WaitTime 2;
    TPWrite "after IDelete " \Num:=n;
  ENDPROC
ENDMODULE
