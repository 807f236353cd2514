MODULE isleep_queued
! @format 3
! @section 8
! @section 11
! @expect ok
! @statement-time 0
! @description ISleep discards the interrupts generated while the number sleeps, not one generated before and still waiting in the queue (here during IDisable): that one is served at IEnable. A timer ordered and then put to sleep falls due unserved; a new order activates the interrupt again (ch. 8: "通常,定义程序(比如,ISignalDI)将激活中断"), so its timer is served (doc/rulings.md R-8-w).
! @output served 1
! @output served 1
! @output served 2
  VAR intnum t;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT t WITH tick;
    IDisable;
    ITimer \Single, 0.1, t;
    WaitTime 0.5;
    ISleep t;
    IEnable;
    WaitTime 0.5;
    TPWrite "served " \Num:=n;
    ITimer \Single, 0.1, t;
    ISleep t;
    WaitTime 0.5;
    TPWrite "served " \Num:=n;
    ITimer \Single, 0.1, t;
    WaitTime 0.5;
    TPWrite "served " \Num:=n;
  ENDPROC
ENDMODULE
