MODULE stepuser
  PROC main()
    Tool 1;
    TPWrite "user";
    Tool 2;
  ENDPROC
ENDMODULE
