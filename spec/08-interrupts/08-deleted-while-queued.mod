MODULE deleted_while_queued
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description An interrupt queued during IDisable whose number is deleted before IEnable is dropped: its trap does not run (doc/rulings.md R-8-c).
! @output served 0
  VAR intnum t;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT t WITH tick;
    IDisable;
    ITimer \Single, 0.1, t;
    WaitTime 1;
    IDelete t;
    IEnable;
    WaitTime 1;
    TPWrite "served " \Num:=n;
  ENDPROC
ENDMODULE
