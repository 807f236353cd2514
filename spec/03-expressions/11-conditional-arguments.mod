MODULE conditional_arguments
! @format 2
! @section 3.11
! @expect ok
! @description Section 3.11: distance := dist(\base ? b, p) passes the optional parameter b on if it is present.
  FUNC num measure(\pos b, pos p)
    VAR num distance;
    distance := dist(\base ? b, p);
    IF Present(b) THEN
      distance := dist(\base:=b, p);
    ELSE
      distance := dist(p);
    ENDIF
    RETURN distance;
  ENDFUNC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
