MODULE steps
  VAR num total := 0;
  VAR num list{3} := [1, 2, 3];
  VAR string label := "start";
  VAR bool flag := FALSE;

  PROC Add(num k)
    VAR num twice;
    twice := 2 * k;
    total := total + k;
    Inner k;
  ENDPROC

  PROC Inner(num k)
    TPWrite "inner " \Num:=k;
  ENDPROC

  PROC main()
    FOR i FROM 1 TO 3 DO
      Add list{i};
    ENDFOR
    TPWrite label;
    IF flag TPWrite "flag set";
    TPWrite "total " \Num:=total;
  ENDPROC
ENDMODULE
