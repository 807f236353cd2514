MODULE isignaldi_single
! @format 3
! @section 8
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description ISignalDI \Single orders one interrupt, at the first change of the input to TriggValue (1 s); the second rising edge (3 s) interrupts no more.
! @output served 1 at 1000
  VAR intnum i1;
  VAR num n := 0;
  VAR num at_ms;
  VAR clock c;
  TRAP edge
    n := n + 1;
    at_ms := Round(ClkRead(c) * 1000);
  ENDTRAP
  PROC main()
    ClkStart c;
    CONNECT i1 WITH edge;
    ISignalDI \Single, di1, 1, i1;
    WaitTime 5;
    TPWrite "served " + NumToStr(n, 0) + " at " + NumToStr(at_ms, 0);
  ENDPROC
ENDMODULE
