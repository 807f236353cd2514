MODULE tools (NOSTEPIN)
  PROC tool()
    RAISE 9;
  ERROR
    RaiseToUser \Continue;
  UNDO
    TPWrite "tool undo";
  ENDPROC
ENDMODULE
