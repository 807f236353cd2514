MODULE idisable_queue
! @format 3
! @section 8
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description While interrupts are disabled (IDisable) they are queued; IEnable serves them first in, first out: the timer's (0.5 s) before the input's (1 s).
! @output disabled []
! @output enabled [tr]
  VAR intnum t;
  VAR intnum r;
  VAR string log := "";
  TRAP on_timer
    log := log + "t";
  ENDTRAP
  TRAP on_rise
    log := log + "r";
  ENDTRAP
  PROC main()
    IDisable;
    CONNECT r WITH on_rise;
    ISignalDI \Single, di1, 1, r;
    CONNECT t WITH on_timer;
    ITimer \Single, 0.5, t;
    WaitTime 1.5;
    TPWrite "disabled [" + log + "]";
    IEnable;
    WaitTime 0.1;
    TPWrite "enabled [" + log + "]";
  ENDPROC
ENDMODULE
