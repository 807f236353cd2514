MODULE deleted_then_reconnected
! @format 3
! @section 8
! @section 4.15
! @expect ok
! @statement-time 0
! @description An interrupt queued during IDisable goes with its number when IDelete deletes it ("取消中断编号的分配"): a CONNECT that then gets the freed number binds a new trap, which the old interrupt never runs; only the new order's interrupt is served (doc/rulings.md R-8-x).
! @output old 0 new 1
  VAR intnum a;
  VAR intnum b;
  VAR num old_n := 0;
  VAR num new_n := 0;
  TRAP old_trap
    old_n := old_n + 1;
  ENDTRAP
  TRAP new_trap
    new_n := new_n + 1;
  ENDTRAP
  PROC main()
    CONNECT a WITH old_trap;
    IDisable;
    ITimer \Single, 0.1, a;
    WaitTime 0.5;
    IDelete a;
    CONNECT b WITH new_trap;
    ITimer \Single, 0.1, b;
    WaitTime 0.5;
    IEnable;
    WaitTime 0.5;
    TPWrite "old " + NumToStr(old_n, 0) + " new " + NumToStr(new_n, 0);
  ENDPROC
ENDMODULE
