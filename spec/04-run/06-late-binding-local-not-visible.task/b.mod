MODULE lib
  LOCAL PROC secret()
    TPWrite "secret of lib";
  ENDPROC
ENDMODULE
