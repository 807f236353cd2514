MODULE trapstep
  ! Stepping through interrupts (doc/rulings.md R-8-z): a timer's trap served during a wait is
  ! entered by step and run whole by next; an interrupt queued during IDisable is served when
  ! IEnable is done, at the entry of the next statement.
  VAR intnum t;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
    TPWrite "tick " \Num:=n;
  ENDTRAP
  PROC main()
    CONNECT t WITH tick;
    ITimer \Single, 0.1, t;
    WaitTime 0.25;
    ITimer \Single, 0.1, t;
    WaitTime 0.25;
    IDisable;
    ITimer \Single, 0.1, t;
    WaitTime 0.25;
    TPWrite "n " \Num:=n;
    IEnable;
    TPWrite "n " \Num:=n;
  ENDPROC
ENDMODULE
