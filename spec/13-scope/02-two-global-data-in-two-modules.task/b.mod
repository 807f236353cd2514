MODULE cell
  PERS num total := 0;
ENDMODULE
