MODULE MainModule
  VAR num total := 0;
  VAR num calls;
  VAR pos path{3};
  FUNC num sq(num x)
    Incr calls;
    RETURN x * x;
  ENDFUNC
  PROC main()
    VAR num i;
    FOR i FROM 1 TO 3 DO
      total := total + sq(i);
      path{i}.x := total / 2;
    ENDFOR
    TPWrite "total = " \Num:=total;
    TPWrite "last = " \Pos:=path{3};
  ENDPROC
ENDMODULE
