MODULE tools (NOSTEPIN)
  PROC tool()
    RAISE 7;
  ERROR
    RaiseToUser \BreakOff;
  ENDPROC
ENDMODULE
