MODULE tools (NOSTEPIN)
  PROC outer()
    inner;
    TPWrite "outer goes on";
  ENDPROC
  PROC inner()
    VAR num x;
    x := 10 / divisor;
    TPWrite "inner x " \Num:=x;
  ERROR
    TPWrite "inner handler";
    RaiseToUser \Continue;
  ENDPROC
ENDMODULE
