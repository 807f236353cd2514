MODULE exit_cycle_not_modelled
! @format 3
! @section 13
! @section 5.1
! @expect ok
! @description ExitCycle (ABB's RAPID reference, ExitCycle: breaks the current cycle and moves the program pointer to the first instruction of main; in continuous mode the next cycle starts, in cycle mode execution stops there) abandons the active routines, whose UNDO handlers then run (§1.2), an outcome no installed routine can give the engines yet: rapid-sem does not model it (exit 4 at the call; doc/rulings.md R-13-sys6).
! @output cycle 1
! @exit 4
! @error ExitCycle 14:5
  VAR num cycle := 0;
  PROC main()
    Incr cycle;
    TPWrite "cycle " \Num:=cycle;
    ExitCycle;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
