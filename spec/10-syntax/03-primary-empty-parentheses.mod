MODULE primary_empty_parentheses
! @section 3.1
! @expect syntax-error 12:11
! @description '(' <expr> ')' requires an expression.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := ();
  ENDPROC
ENDMODULE
