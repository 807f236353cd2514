MODULE settings
  PROC report(string message)
  ENDPROC
ENDMODULE
