MODULE msg_excrtymax
  VAR num n := 0;
  PROC main()
    n := 1 / 0;
  ERROR
    TPWrite "retrying";
    RETRY;
  ENDPROC
ENDMODULE
