MODULE switch_argument_with_value
! @format 2
! @section 3.11
! @section 5.2
! @expect semantic-error 9:19
! @description A switch argument contains no expression (its domain is empty); refused at the backslash.
  VAR num c;
  PROC main()
    c := cosine(1 \rad:=TRUE);
  ENDPROC

  FUNC num cosine(num angle \switch rad)
    IF Present(rad) RETURN angle;
    RETURN angle / 57.29578;
  ENDFUNC
ENDMODULE
