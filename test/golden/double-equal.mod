MODULE cell
  PROC main()
    VAR num a;
    IF a == 1 THEN
      a := 2;
    ENDIF
  ENDPROC
ENDMODULE
