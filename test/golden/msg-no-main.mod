MODULE msg_no_main
  PROC Start()
    TPWrite "hi";
  ENDPROC
  PROC Other()
    TPWrite "other";
  ENDPROC
  PROC WithArg(num x)
    TPWrite "x";
  ENDPROC
ENDMODULE
