MODULE wait_ended_by_trap
! @format 3
! @section 8
! @section 13
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description A wait that only a trap can end is not a deadlock while an interrupt source remains: the timer's trap sets the output WaitDO waits for. Without the timer, the same wait is a deadlock (exit 3).
! @output do1 set by the trap at 700
! @output waiting again
! @exit 3
  VAR intnum t;
  VAR clock c;
  TRAP tick
    SetDO do1, 1;
  ENDTRAP
  PROC main()
    ClkStart c;
    CONNECT t WITH tick;
    ITimer \Single, 0.7, t;
    WaitDO do1, 1;
    TPWrite "do1 set by the trap at " \Num:=Round(ClkRead(c) * 1000);
    TPWrite "waiting again";
    WaitDO do1, 0;
  ENDPROC
ENDMODULE
