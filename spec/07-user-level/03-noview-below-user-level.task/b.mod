MODULE hidden_tools (NOVIEW)
  PROC hidden()
    RAISE 3;
  ERROR
    RaiseToUser \BreakOff;
  ENDPROC
ENDMODULE
