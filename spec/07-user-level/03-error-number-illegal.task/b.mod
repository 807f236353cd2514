MODULE tools (NOSTEPIN)
  PROC tool()
    RAISE 3;
  ERROR
    TPWrite "tool handler";
    RaiseToUser \BreakOff \ErrorNumber:=100;
  ENDPROC
ENDMODULE
