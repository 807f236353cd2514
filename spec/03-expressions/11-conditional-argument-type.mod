MODULE conditional_argument_type
! @format 2
! @section 3.11
! @expect semantic-error 7:17
! @description The parameter passed on conditionally must have the type of the optional parameter it fills; refused at the backslash.
  FUNC num measure(\num b, pos p)
    RETURN dist(\base ? b, p);
  ENDFUNC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
