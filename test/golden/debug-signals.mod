MODULE signals
  VAR num n := 0;
  VAR signaldi diFree;
  PROC main()
    SetDO doLamp, 1;
    WaitTime 1;
    n := n + 1;
    TPWrite "n " \Num:=n;
  ENDPROC
ENDMODULE
