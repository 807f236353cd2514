MODULE cell
  LOCAL VAR string counter;
  LOCAL PROC init()
    counter := "";
  ENDPROC
ENDMODULE
