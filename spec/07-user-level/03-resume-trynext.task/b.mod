MODULE tools (NOSTEPIN)
  PROC tool()
    RAISE 5;
    TPWrite "inner goes on";
  ERROR
    TPWrite "inner handler";
    RaiseToUser \Resume \ErrorNumber:=12;
  ENDPROC
ENDMODULE
