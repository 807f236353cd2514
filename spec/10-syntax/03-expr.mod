MODULE expr
! @section 3.1
! @expect ok
! @description <expr> ::= [ NOT ] <logical term> { ( OR | XOR ) <logical term> }.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := a;
    x := NOT a;
    x := a OR b;
    x := a XOR b OR c;
    x := NOT a OR b XOR c;
    x := NOT (a AND b);
  ENDPROC
ENDMODULE
