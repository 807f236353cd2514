MODULE bench_calls
  ! 1,000,000 calls with an IN, an INOUT, a VAR and a PERS argument.
  PERS num calls_made := 0;

  PROC update(num a, INOUT num b, VAR num c, PERS num d)
    b := b + a;
    c := c + 1;
    d := d + 1;
  ENDPROC

  PROC main()
    VAR num b := 0;
    VAR num c := 0;
    calls_made := 0;
    FOR k FROM 1 TO 1000000 DO
      update 2, b, c, calls_made;
    ENDFOR
    TPWrite "b=" \Num:=b;
    TPWrite "c=" \Num:=c;
    TPWrite "d=" \Num:=calls_made;
  ENDPROC
ENDMODULE
