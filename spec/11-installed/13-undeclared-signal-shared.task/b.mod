MODULE signal_reader
! @task T_B
  PROC main()
    WaitDO doReady, 1;
    TPWrite "B saw " \Num := DOutput(doReady);
  ENDPROC
ENDMODULE
