MODULE settings
  LOCAL VAR num secret := 1;
ENDMODULE
