MODULE ProgData
  CONST string greeting := "program file: two modules, one task";
ENDMODULE
