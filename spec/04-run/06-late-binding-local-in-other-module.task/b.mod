MODULE lib
  LOCAL PROC secret()
    TPWrite "secret of lib";
  ENDPROC
  PROC shared()
    TPWrite "global of lib";
  ENDPROC
ENDMODULE
