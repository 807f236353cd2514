MODULE initial_values
  CONST num a := b;
  CONST num b := a;
  VAR num big := 1E39;
  PROC main()
    VAR num x := 1 / 0;
    TPWrite "x" \Num:=x;
  ENDPROC
ENDMODULE
