MODULE primary
! @section 3.1
! @expect ok
! @description <primary>: literal, variable (entire, element, component), function call, aggregate, '(' <expr> ')'.
  VAR num a;
  VAR num b;
  VAR num arr{2};
  VAR pos p;
  VAR bool x;
  PROC main()
    x := 1;
    x := "s" = "t";
    x := TRUE;
    x := a;
    x := arr{1};
    x := p.x;
    x := f(1);
    x := [1, 2] = [a, b];
    x := (a);
    x := (NOT b);
  ENDPROC
ENDMODULE
