MODULE isignalai_case
! @format 3
! @section 8
! @expect ok
! @io io/analog.io
! @statement-time 0
! @description ISignalAI AIO_ABOVE_HIGH: an interrupt at a change of the input where it is above HighValue and either was not before, or moved more than DeltaValue (in the \DPos direction) from its value at the last interrupt (doc/rulings.md R-8-k). Input 3, 6, 8, 2, 7 at 1..5 s: with DeltaValue 0 at 2, 3 and 5 s; with DeltaValue 3 at 2 and 5 s.
! @output adaad
  VAR intnum a;
  VAR intnum d;
  VAR string log := "";
  TRAP above
    IF INTNO = a THEN
      log := log + "a";
    ELSE
      log := log + "d";
    ENDIF
  ENDTRAP
  PROC main()
    CONNECT a WITH above;
    ISignalAI ai1, AIO_ABOVE_HIGH, 5, 0, 0, a;
    CONNECT d WITH above;
    ISignalAI ai1, AIO_ABOVE_HIGH, 5, 0, 3 \DPos, d;
    WaitTime 6;
    TPWrite log;
  ENDPROC
ENDMODULE
