MODULE tools (NOSTEPIN)
  PROC outer()
    inner;
    TPWrite "outer goes on";
  ERROR
    TPWrite "outer handler";
    RAISE;
  UNDO
    TPWrite "outer undo";
  ENDPROC
  PROC inner()
    RAISE 7;
    TPWrite "inner goes on";
  ERROR
    TPWrite "inner handler";
    RaiseToUser \BreakOff;
  UNDO
    TPWrite "inner undo";
  ENDPROC
ENDMODULE
