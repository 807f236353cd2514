MODULE queue_full
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description The interrupt queue holds 30 interrupts (doc/rulings.md R-8-c): of the 50 a 0.1 s timer orders during 5 s of IDisable, the first 30 are served at IEnable (when the next statement is entered) and the rest are discarded.
! @output served 30
  VAR intnum t;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT t WITH tick;
    IDisable;
    ITimer 0.1, t;
    WaitTime 5.05;
    IEnable;
    TPWrite "served " \Num:=n;
    IDelete t;
  ENDPROC
ENDMODULE
