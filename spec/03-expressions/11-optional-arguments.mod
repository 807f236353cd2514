MODULE optional_arguments
! @format 2
! @section 3.11
! @expect ok
! @description Section 3.11: dist(pnt:=p2) and dist(\base:=p1, pnt:=p2); an optional argument may be left out.
  VAR pos p1;
  VAR pos p2;
  VAR num d;
  PROC main()
    d := dist(pnt:=p2);
    d := dist(\base:=p1, pnt:=p2);
    d := dist(p2);
    d := dist(\base:=p1, p2);
  ENDPROC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
