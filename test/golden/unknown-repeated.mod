MODULE cell
  PROC main()
    SetDO doGripper, 1;
    Grip \Close;
    WaitTime 0.5;
    grip \Open;
    SetDO DOGRIPPER, 0;
    SetDO doGripper, 1;
  ENDPROC
ENDMODULE
