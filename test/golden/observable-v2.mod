MODULE observable_v2
  RECORD pair
    num x;
    num y;
  ENDRECORD
  VAR num big;
  VAR num tenth;
  VAR num third;
  VAR num zero;
  VAR num huge;
  VAR dnum dthird;
  VAR num a{3};
  VAR num m{2,3};
  VAR pair ps{2};
  VAR num divisor;
  VAR num n;

  FUNC num half(num v)
    VAR num w := 2;
    RETURN v / w;
  ENDFUNC

  PROC bump(INOUT num k, \switch twice, \num by)
    k := k + 1;
  ENDPROC

  PROC both(INOUT num arr{*}, INOUT num k)
    k := 5;
    arr{1} := 6;
  ENDPROC

  PROC divide(INOUT num k)
    k := k / divisor;
  ENDPROC

  PROC relay(INOUT num k)
    divide k;
  ENDPROC

  PROC main()
    big := 9E+09;
    tenth := 0.1;
    third := 1 / 3;
    zero := -0;
    huge := 3.4E+38;
    dthird := 1 / 3;
    a{2} := 123456789;
    m{2,3} := 6;
    ps{2}.y := half(5);
    bump a{1}, \twice;
    Incr ps{1}.x;
    both a, a{2};
    FOR i FROM 1 TO 2 DO
      n := n + i;
    ENDFOR
    relay a{3};
    divisor := 1;
    n := 7 / divisor;
    TPWrite "n " \Num:=n;
    n := a{n};
    Stop;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_DIVZERO AND divisor = 0 THEN
      divisor := 4;
      RETRY;
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
