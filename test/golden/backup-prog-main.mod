MODULE ProgMain
  PROC main()
    TPWrite greeting;
  ENDPROC
ENDMODULE
