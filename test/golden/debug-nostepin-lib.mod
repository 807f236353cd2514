MODULE steplib(NOSTEPIN)
  PROC Tool(num k)
    TPWrite "tool " \Num:=k;
    Helper;
  ENDPROC
  PROC Helper()
    TPWrite "helper";
  ENDPROC
ENDMODULE
