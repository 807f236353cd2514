MODULE bad
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
