MODULE result_copies
! @format 3
! @section 4.5
! @section 5.2
! @section 5.5
! @expect ok
! @description A record a function returns is a value of the target's own once assigned: returned from the function's in parameter (a copy of the argument), from its routine data, from module data, from an array element, or from a FOR loop of calls, changing the target afterwards changes nothing else (the argument, the module data, the element, an earlier result), and changing those changes no target.
! @output a.x=1 b.x=9
! @output made.x=4 again.x=5
! @output g.x=7 c.x=8
! @output e{1}.x=2 d.x=6
! @output q1.x=1 q2.x=2 q3.x=3
! @exit 0
  VAR pos g := [7, 0, 0];
  VAR pos e{2} := [[2, 0, 0], [3, 0, 0]];

  FUNC pos same(pos v)
    RETURN v;
  ENDFUNC

  FUNC pos made(num x)
    VAR pos p;
    p.x := x;
    IF x > 100 THEN
      RETURN p;
    ENDIF
    RETURN p;
  ENDFUNC

  FUNC pos global_one()
    RETURN g;
  ENDFUNC

  FUNC pos element(num i)
    RETURN e{i};
  ENDFUNC

  PROC main()
    VAR pos a := [1, 0, 0];
    VAR pos b;
    VAR pos c;
    VAR pos d;
    VAR pos m1;
    VAR pos m2;
    VAR pos q{3};
    VAR pos last;
    b := same(a);
    b.x := 9;
    TPWrite "a.x=" + NumToStr(a.x, 0) + " b.x=" + NumToStr(b.x, 0);
    m1 := made(4);
    m2 := made(5);
    TPWrite "made.x=" + NumToStr(m1.x, 0) + " again.x=" + NumToStr(m2.x, 0);
    c := global_one();
    c.x := 8;
    TPWrite "g.x=" + NumToStr(g.x, 0) + " c.x=" + NumToStr(c.x, 0);
    d := element(1);
    d.x := 6;
    TPWrite "e{1}.x=" + NumToStr(e{1}.x, 0) + " d.x=" + NumToStr(d.x, 0);
    FOR i FROM 1 TO 3 DO
      last := made(i);
      q{i} := last;
      last.x := 0;
    ENDFOR
    TPWrite "q1.x=" + NumToStr(q{1}.x, 0) + " q2.x=" + NumToStr(q{2}.x, 0) + " q3.x=" + NumToStr(q{3}.x, 0);
  ENDPROC
ENDMODULE
