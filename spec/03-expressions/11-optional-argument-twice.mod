MODULE optional_argument_twice
! @format 2
! @section 3.11
! @expect semantic-error 10:25
! @description An optional argument given twice; the second is refused at its backslash.
  VAR pos p1;
  VAR pos p2;
  VAR num d;
  PROC main()
    d := dist(\base:=p1 \base:=p1, p2);
  ENDPROC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
