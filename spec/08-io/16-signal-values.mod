MODULE signal_values
! @format 3
! @section 2.16
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description The signals of the I/O configuration are installed objects of the signal types; in value context a signal is its value (section 2.16), which DInput, DOutput, GInput, AInput and TestDI read too.
! @output di1=0
! @output di2=1
! @output do2=1
! @output gi1=5
! @output ai1 TRUE
! @output TestDI FALSE
! @output TestDI TRUE
! @output sum=6
  PROC main()
    TPWrite "di1=" \Num:=di1;
    TPWrite "di2=" \Num:=DInput(di2);
    TPWrite "do2=" \Num:=DOutput(do2);
    TPWrite "gi1=" \Num:=GInput(gi1);
    TPWrite "ai1 " \Bool:=(AInput(ai1) = 2.5);
    TPWrite "TestDI " \Bool:=TestDI(di1);
    TPWrite "TestDI " \Bool:=TestDI(di2);
    TPWrite "sum=" \Num:=gi1 + di2;
  ENDPROC
ENDMODULE
