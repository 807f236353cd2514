MODULE relation
! @section 3.1
! @expect ok
! @description <relation> ::= <simple expr> [ <relop> <simple expr> ] with every <relop>: '<' '<=' '=' '>' '>=' '<>'.
  VAR num a;
  VAR num b;
  VAR bool x;
  PROC main()
    x := a < b;
    x := a <= b;
    x := a = b;
    x := a > b;
    x := a >= b;
    x := a <> b;
    x := a + 1 < b * 2;
  ENDPROC
ENDMODULE
