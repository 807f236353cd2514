MODULE isignalao_go
! @format 3
! @section 8
! @expect ok
! @io io/outputs.io
! @statement-time 0
! @description ISignalAO and ISignalGO interrupt at the program's own changes of an output. ISignalAO AIO_BETWEEN 5..10 with DeltaValue 0: the output set to 3, 7, 8, 8 (no change), 12 interrupts at 7 (the condition begins to hold) and 8 (it holds and the value moved, doc/rulings.md R-8-k). ISignalGO at every change of the group's value (2 to 5, 5 to 6; setting 6 again is no change); with \Single at the first change only.
! @output ao 2
! @output go 2
! @output single 1
  VAR intnum a;
  VAR intnum g;
  VAR intnum s;
  VAR num na := 0;
  VAR num ng := 0;
  VAR num ns := 0;
  TRAP count
    TEST INTNO
    CASE a:
      na := na + 1;
    CASE g:
      ng := ng + 1;
    CASE s:
      ns := ns + 1;
    ENDTEST
  ENDTRAP
  PROC main()
    CONNECT a WITH count;
    ISignalAO ao1, AIO_BETWEEN, 10, 5, 0, a;
    CONNECT g WITH count;
    ISignalGO go1, g;
    CONNECT s WITH count;
    ISignalGO \Single, go1, s;
    SetAO ao1, 3;
    SetAO ao1, 7;
    SetAO ao1, 8;
    SetAO ao1, 8;
    SetAO ao1, 12;
    SetGO go1, 5;
    SetGO go1, 6;
    SetGO go1, 6;
    WaitTime 0.1;
    TPWrite "ao " \Num:=na;
    TPWrite "go " \Num:=ng;
    TPWrite "single " \Num:=ns;
  ENDPROC
ENDMODULE
