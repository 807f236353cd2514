MODULE no_nesting
! @format 3
! @section 8
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description Interrupts are not served at trap level: the rising edge at 1 s comes while the timer's trap waits (0.5 s to 1.5 s); it is queued and its trap runs when the first trap has ended, at 1.5 s.
! @output <slow slow> edge
! @output edge served at 1500
  VAR intnum t;
  VAR intnum r;
  VAR string log := "";
  VAR num edge_ms;
  VAR clock c;
  TRAP slow
    log := log + "<slow";
    WaitTime 1;
    log := log + " slow>";
  ENDTRAP
  TRAP edge
    log := log + " edge";
    edge_ms := Round(ClkRead(c) * 1000);
  ENDTRAP
  PROC main()
    ClkStart c;
    CONNECT t WITH slow;
    ITimer \Single, 0.5, t;
    CONNECT r WITH edge;
    ISignalDI \Single, di1, 1, r;
    WaitTime 3;
    TPWrite log;
    TPWrite "edge served at " \Num:=edge_ms;
  ENDPROC
ENDMODULE
