MODULE Events
  ! The event routines of SYS.cfg's CAB_EXEC_HOOKS run around main as a controller runs them
  ! at power on and a start from the beginning (doc/rulings.md R-bk-8).
  VAR num cycle := 7;
  CONST jointtarget home := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget far := [[30, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC power_on()
    phase := 1;
    TPWrite "rob1: power on";
  ENDPROC

  PROC reset_cycle()
    ! PP to main: the cycle's data back to its start. ExitCycle ends the event routine.
    cycle := 0;
    TPWrite "rob1: reset";
    ExitCycle;
    TPWrite "rob1: never written";
  ENDPROC

  PROC start_first()
    TPWrite "rob1: start, sequence number 1";
  ENDPROC

  PROC start_second()
    phase := 2;
    TPWrite "rob1: start, sequence number 2";
  ENDPROC

  PROC main()
    TPWrite "rob1: main, cycle " \Num:=cycle;
    MoveAbsJ home, v1000, fine, tool0;
    MoveAbsJ far, v200, fine, tool0;
    cycle := cycle + 1;
    cycle_done := TRUE;
  ENDPROC

  PROC on_stop()
    phase := 3;
    TPWrite "rob1: stop after cycle " \Num:=cycle;
    ! ABB allows no motion here: a warning says so, and the move is made as written.
    go_home;
  ENDPROC

  PROC go_home()
    MoveAbsJ home, v1000, fine, tool0;
  ENDPROC

  PROC on_restart()
    TPWrite "rob1: restart (debug only)";
  ENDPROC

  PROC on_step()
    TPWrite "rob1: step (debug only)";
  ENDPROC

  PROC on_qstop()
    TPWrite "rob1: quick stop (never)";
  ENDPROC
ENDMODULE
