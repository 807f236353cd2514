MODULE optional_argument_out_of_order
! @format 2
! @section 3.11
! @expect semantic-error 10:18
! @description Present arguments stand in the order of the parameters; \base after pnt is refused at the backslash.
  VAR pos p1;
  VAR pos p2;
  VAR num d;
  PROC main()
    d := dist(p2 \base:=p1);
  ENDPROC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
