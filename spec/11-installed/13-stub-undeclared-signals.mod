MODULE stub_undeclared_signals
! @format 3
! @section 13
! @section 2.16
! @options allow-unknown
! @options stub-unmodelled
! @expect ok
! @description Under --allow-unknown --stub-unmodelled, a name no module declares that is passed where a routine takes a signal (installed: Set, SetDO, DOutput, DInput, SetAO, AOutput; or the program's own, Raise1's VAR signaldo) is a virtual signal of that parameter's type, at 0 (doc/rulings.md R-13-aa): outputs keep what the program writes, inputs stay 0. A declared name, here the parameter out, is never made a signal.
! @output clamp 0
! @output clamp 1
! @output sensor 0
! @output flow 2.5
! @output via parameter 1
  PROC main()
    TPWrite "clamp " \Num:=DOutput(doClamp);
    Set doClamp;
    TPWrite "clamp " \Num:=DOutput(doClamp);
    TPWrite "sensor " \Num:=DInput(diSensor);
    SetAO aoFlow, 2.5;
    TPWrite "flow " \Num:=AOutput(aoFlow);
    Raise1 doLamp;
  ENDPROC
  PROC Raise1(VAR signaldo out)
    SetDO out, 1;
    TPWrite "via parameter " \Num:=DOutput(out);
  ENDPROC
ENDMODULE
