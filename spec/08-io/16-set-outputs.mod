MODULE set_outputs
! @format 3
! @section 2.16
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description Set, Reset, InvertDO, SetDO, SetAO, SetGO and assignment to an output signal (section 2.16: an output accepts an update by value) change the signal at once.
! @output set 1
! @output reset 0
! @output invert 1
! @output invert 0
! @output SetDO 1
! @output assigned 0
! @output ao1=3
! @output go1=9
  PROC main()
    Set do1;
    TPWrite "set " \Num:=do1;
    Reset do1;
    TPWrite "reset " \Num:=DOutput(do1);
    InvertDO do1;
    TPWrite "invert " \Num:=do1;
    InvertDO do1;
    TPWrite "invert " \Num:=do1;
    SetDO do1, 1;
    TPWrite "SetDO " \Num:=do1;
    do1 := 0;
    TPWrite "assigned " \Num:=do1;
    SetAO ao1, 3;
    TPWrite "ao1=" \Num:=AOutput(ao1);
    SetGO go1, 9;
    TPWrite "go1=" \Num:=GOutput(go1);
  ENDPROC
ENDMODULE
