MODULE msg_undeclared_signal
  PERS tooldata tGripper := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];
  PROC main()
    SetDO doGripper, 1;
    WaitDI diGripper, 1;
  ENDPROC
ENDMODULE
