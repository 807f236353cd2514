MODULE settings
  VAR string level := "low";
ENDMODULE
