MODULE settings
  TASK PERS num state := 0;
ENDMODULE
