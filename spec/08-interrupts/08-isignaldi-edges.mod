MODULE isignaldi_edges
! @format 3
! @section 8
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description ISignalDI orders an interrupt at each change of the input to TriggValue: 1 the rising edges, 0 the falling ones, 2 both; one trap serves the three, telling them apart by INTNO; interrupts of the same instant are served in the order they occurred (first in, first out).
! @output rbfbrbfb
  VAR intnum rising;
  VAR intnum falling;
  VAR intnum both;
  VAR string log := "";
  TRAP edge
    IF INTNO = rising THEN
      log := log + "r";
    ELSEIF INTNO = falling THEN
      log := log + "f";
    ELSEIF INTNO = both THEN
      log := log + "b";
    ENDIF
  ENDTRAP
  PROC main()
    CONNECT rising WITH edge;
    ISignalDI di1, 1, rising;
    CONNECT falling WITH edge;
    ISignalDI di1, 0, falling;
    CONNECT both WITH edge;
    ISignalDI di1, 2, both;
    WaitTime 5;
    TPWrite log;
  ENDPROC
ENDMODULE
