MODULE optional_argument_without_value
! @format 2
! @section 3.11
! @expect semantic-error 9:15
! @description Only a switch argument goes without a value: \base of type pos needs one; refused at the backslash.
  VAR pos p2;
  VAR num d;
  PROC main()
    d := dist(\base, p2);
  ENDPROC

  FUNC num dist(\pos base, pos pnt)
    IF Present(base) RETURN pnt.x - base.x;
    RETURN pnt.x;
  ENDFUNC
ENDMODULE
