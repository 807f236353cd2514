MODULE conditional_argument_required
! @format 2
! @section 3.11
! @expect semantic-error 7:25
! @description The parameter named in a conditional argument must be optional (section 3.11); a required parameter is refused at its name.
  FUNC num measure(pos b, pos p)
    RETURN dist(\base ? b, p);
  ENDFUNC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
