MODULE cell
  LOCAL VAR num level;
  PROC main()
    level := 3;
  ENDPROC
ENDMODULE
