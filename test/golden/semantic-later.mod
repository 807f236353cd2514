MODULE m
  VAR num a;
  PROC p()
    a := "John";
  ENDPROC
ENDMODULE
