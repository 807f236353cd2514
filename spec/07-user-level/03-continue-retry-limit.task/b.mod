MODULE tools (NOSTEPIN)
  PROC tool()
    RAISE 6;
  ERROR
    RaiseToUser \Continue;
  ENDPROC
ENDMODULE
