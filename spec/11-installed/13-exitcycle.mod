MODULE exit_cycle
! @format 3
! @section 13
! @section 1.2
! @expect ok
! @description ExitCycle (ABB's ExitCycle: the current cycle is broken and the program pointer moves to main's first instruction, the next cycle starting; the values of variables and persistents, open files and defined interrupts are not affected; doc/rulings.md R-13-exitcycle1): called two routines deep, it abandons them, each running its UNDO handler innermost first (§1.2), then main starts again. Module data keeps its value (the count goes on), main's routine data takes its initial value again, the interrupt number stays connected (a second CONNECT is ERR_ALRDYCNT, handled) and the file opened in the first cycle is still open. The third cycle ends main and the run.
! @output cycle 1 fresh 1
! @output undo inner
! @output undo outer
! @output undo main
! @output cycle 2 fresh 1
! @output connected already
! @output file still open
! @output undo inner
! @output undo outer
! @output undo main
! @output cycle 3 fresh 1
! @output the end
  VAR num cycle := 0;
  VAR intnum tick;
  VAR iodev log;
  PROC inner()
    ExitCycle;
    TPWrite "not reached";
  UNDO
    TPWrite "undo inner";
  ENDPROC
  PROC outer()
    inner;
    TPWrite "not reached";
  UNDO
    TPWrite "undo outer";
  ENDPROC
  TRAP on_tick
  ENDTRAP
  PROC main()
    VAR num fresh := 0;
    Incr cycle;
    Incr fresh;
    TPWrite "cycle " + NumToStr(cycle, 0) + " fresh " + NumToStr(fresh, 0);
    IF cycle = 1 THEN
      CONNECT tick WITH on_tick;
      Open "HOME:/cycles.txt", log \Write;
    ELSEIF cycle = 2 THEN
      CONNECT tick WITH on_tick;
    ENDIF
    IF cycle = 2 THEN
      Write log, "cycle 2";
      TPWrite "file still open";
    ENDIF
    IF cycle < 3 outer;
    TPWrite "the end";
    Close log;
  ERROR
    IF ERRNO = ERR_ALRDYCNT THEN
      TPWrite "connected already";
      TRYNEXT;
    ENDIF
  UNDO
    TPWrite "undo main";
  ENDPROC
ENDMODULE
