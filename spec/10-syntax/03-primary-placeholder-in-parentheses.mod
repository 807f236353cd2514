MODULE primary_placeholder_in_parenthes
! @section 3.1
! @expect syntax-error 12:11
! @description '(' <expr> ')': <EXP> is an <expression>, not an <expr>.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := (<EXP>);
  ENDPROC
ENDMODULE
