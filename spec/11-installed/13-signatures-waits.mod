MODULE sig_waits
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description The waits with every optional argument ABB documents (RAPID Instructions, Functions and Data types: WaitTime, WaitUntil, WaitDI, WaitDO, WaitAI, WaitAO, WaitGI, WaitGO): \MaxTime, \TimeFlag, \PollRate, \InPos, the comparison switches, \ValueAtTimeout | \DvalueAtTimeout and the visualization group \Visualize \Header \Message | \MsgArray \Wrap \Icon \Image \VisualizeTime \UIActiveSignal.
  VAR signaldi diReady;
  VAR signaldo doBusy;
  VAR signaldo doShown;
  VAR signalai aiPressure;
  VAR signalao aoFlow;
  VAR signalgi giCode;
  VAR signalgo goCode;
  VAR bool late;
  VAR num seen;
  VAR dnum dseen;
  CONST string lines{2} := ["Waiting for the part", "Check the clamp"];
  PROC main()
    WaitTime 0.5;
    WaitTime \InPos, 0;
    WaitUntil \InPos, late \MaxTime:=5 \TimeFlag:=late \PollRate:=0.1;
    WaitUntil late \Visualize \Header:="Cell" \Message:="Waiting" \Icon:=iconInfo;
    WaitDI diReady, 1;
    WaitDI diReady, high \MaxTime:=2 \TimeFlag:=late;
    WaitDI diReady, 1 \Visualize \Header:="Cell" \MsgArray:=lines \Wrap \Icon:=iconWarning
      \Image:="part.png" \VisualizeTime:=3 \UIActiveSignal:=doShown;
    WaitDO doBusy, 0 \MaxTime:=1 \Visualize \Message:="Busy";
    WaitAI aiPressure, 4.5;
    WaitAI aiPressure \GT, 4.5 \MaxTime:=10 \ValueAtTimeout:=seen;
    WaitAO aoFlow \LT, 2 \Visualize \Header:="Flow" \Message:="low";
    WaitGI giCode, 12;
    WaitGI giCode \NOTEQ, 0 \MaxTime:=3 \ValueAtTimeout:=seen;
    WaitGI giCode \GT, dseen \MaxTime:=3 \DvalueAtTimeout:=dseen;
    WaitGO goCode \LT, 100 \Visualize \MsgArray:=lines \Wrap;
  ENDPROC
ENDMODULE
