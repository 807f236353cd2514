MODULE logical_term
! @section 3.1
! @expect ok
! @description <logical term> ::= <relation> { AND <relation> }.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := a AND b;
    x := a AND b AND c;
    x := a AND (NOT b);
  ENDPROC
ENDMODULE
