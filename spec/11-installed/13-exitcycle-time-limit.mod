MODULE exit_cycle_time_limit
! @format 3
! @section 13
! @section 1.4
! @expect ok
! @statement-time 0
! @max-time 0.45
! @description A program that breaks every cycle with ExitCycle never ends by itself; --max-time bounds it as any loop (doc/rulings.md R-13-exitcycle1): each cycle waits 0.1 s and counts, the count kept in module data across cycles; the wait of the fifth cycle passes 0.45 s and the run ends there (exit 3).
! @output cycle 1
! @output cycle 2
! @output cycle 3
! @output cycle 4
! @exit 3
  VAR num cycle := 0;
  PROC main()
    WaitTime 0.1;
    Incr cycle;
    TPWrite "cycle " \Num:=cycle;
    ExitCycle;
  ENDPROC
ENDMODULE
