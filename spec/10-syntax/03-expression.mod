MODULE expression
! @section 3.1
! @expect ok
! @description <expression> ::= <expr> | <EXP>.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a + 1;
    x := <EXP>;
  ENDPROC
ENDMODULE
