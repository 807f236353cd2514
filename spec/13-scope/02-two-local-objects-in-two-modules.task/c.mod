MODULE report
  VAR bool counter;
  PROC init_report()
    counter := FALSE;
  ENDPROC
ENDMODULE
