MODULE term
! @section 3.1
! @expect ok
! @description <term> ::= <primary> { <mulop> <primary> } with <mulop> ::= '*' | '/' | DIV | MOD.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a * b;
    x := a / b;
    x := a DIV b;
    x := a MOD b;
    x := a * b / c DIV d MOD e;
  ENDPROC
ENDMODULE
