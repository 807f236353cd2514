MODULE optional_argument_unknown
! @format 2
! @section 3.11
! @expect semantic-error 10:15
! @description An optional argument must name an optional parameter; refused at the backslash.
  VAR pos p1;
  VAR pos p2;
  VAR num d;
  PROC main()
    d := dist(\origin:=p1, p2);
  ENDPROC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
