MODULE io
  PROC main()
    SetDO doGripper, 1;
    WaitDI diPartPresent, 1;
    Grip \Close;
  ENDPROC
ENDMODULE
