MODULE isleep_iwatch
! @format 3
! @section 8
! @section 11
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description ISleep deactivates one interrupt: what it generates meanwhile is discarded without any trap (the rising edge at 1 s); IWatch activates it again (the rising edge at 3 s is served).
! @output served 1 at 3000
  VAR intnum r;
  VAR num n := 0;
  VAR num at_ms;
  VAR clock c;
  TRAP edge
    n := n + 1;
    at_ms := Round(ClkRead(c) * 1000);
  ENDTRAP
  PROC main()
    ClkStart c;
    CONNECT r WITH edge;
    ISignalDI di1, 1, r;
    ISleep r;
    WaitTime 2;
    IWatch r;
    WaitTime 3;
    TPWrite "served " + NumToStr(n, 0) + " at " + NumToStr(at_ms, 0);
  ENDPROC
ENDMODULE
