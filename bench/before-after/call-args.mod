MODULE BaCallArgs
  ! Calls with IN, INOUT, VAR and PERS arguments, a function with a VAR parameter, 300,000
  ! rounds (bench/before-after.sh).
  PERS num ba_pers := 0;

  PROC advance(num a, INOUT num b, VAR num c, PERS num d)
    b := b + a;
    c := c + 1;
    d := d + 1;
  ENDPROC

  FUNC num twice(num a, VAR num c)
    c := c + 1;
    RETURN a * 2;
  ENDFUNC

  PROC main()
    VAR num b := 0;
    VAR num c := 0;
    VAR num t := 0;
    ba_pers := 0;
    FOR k FROM 1 TO 300000 DO
      advance k MOD 7, b, c, ba_pers;
      t := t + twice(k MOD 5, c);
    ENDFOR
    TPWrite "b=" \Num:=b;
    TPWrite "c=" \Num:=c;
    TPWrite "t=" \Num:=t;
    TPWrite "pers=" \Num:=ba_pers;
  ENDPROC
ENDMODULE
