MODULE simple_expr
! @section 3.1
! @expect ok
! @description <simple expr> ::= [ <addop> ] <term> { <addop> <term> } with <addop> ::= '+' | '-'.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a + b;
    x := a - b + c;
    x := -a;
    x := +a;
    x := -a + b - c;
    x := a * (-b);
    x := (-1);
  ENDPROC
ENDMODULE
