MODULE exit_cycle_trap
! @format 3
! @section 13
! @section 8
! @expect ok
! @statement-time 0
! @description ExitCycle in a trap (ABB's ExitCycle: the instructions started but not finished are interrupted at every execution level, normal and trap; doc/rulings.md R-13-exitcycle1): the timer's trap at 0.3 s breaks the cycle while main waits in WaitTime 10; the trap and main are abandoned, main's UNDO handler runs, and main starts again at 0.3 s with the interrupt still defined, which it deletes.
! @output cycle 1 at 0.0
! @output trap at 0.3
! @output undo main
! @output cycle 2 at 0.3
  VAR num cycle := 0;
  VAR intnum tick;
  VAR clock c;
  TRAP on_tick
    TPWrite "trap at " + NumToStr(ClkRead(c), 1);
    ExitCycle;
  ENDTRAP
  PROC main()
    Incr cycle;
    IF cycle = 1 THEN
      ClkStart c;
      TPWrite "cycle 1 at " + NumToStr(ClkRead(c), 1);
      CONNECT tick WITH on_tick;
      ITimer \Single, 0.3, tick;
      WaitTime 10;
      TPWrite "not reached";
    ENDIF
    TPWrite "cycle 2 at " + NumToStr(ClkRead(c), 1);
    IDelete tick;
  UNDO
    TPWrite "undo main";
  ENDPROC
ENDMODULE
