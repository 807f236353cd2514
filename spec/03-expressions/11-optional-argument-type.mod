MODULE optional_argument_type
! @format 2
! @section 3.11
! @expect semantic-error 9:15
! @description An optional argument's type must equal its parameter's; refused at the backslash.
  VAR pos p2;
  VAR num d;
  PROC main()
    d := dist(\base:=5, p2);
  ENDPROC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
