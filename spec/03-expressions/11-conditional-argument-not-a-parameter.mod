MODULE conditional_argument_not_a
! @format 2
! @section 3.11
! @expect semantic-error 8:25
! @description A conditional argument refers to a parameter (<conditional function argument> ::= '\' <ident> '?' <parameter>); a module variable is refused at its name.
  VAR pos home;
  FUNC num measure(pos p)
    RETURN dist(\base ? home, p);
  ENDFUNC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
