MODULE conditional_argument
! @format 3
! @section 3.11
! @section 5.2
! @expect ok
! @description Section 3.11's dist(\base ? b, p): the conditional argument is present, with b's value, exactly when the caller's optional parameter b is present; otherwise it is left out.
! @output base 7
! @output no base
! @exit 0
  FUNC num dist(\num base, num pnt)
    IF Present(base) THEN
      TPWrite "base " \Num:=base;
      RETURN pnt - base;
    ENDIF
    TPWrite "no base";
    RETURN pnt;
  ENDFUNC
  PROC measure(\num b)
    VAR num distance;
    distance := dist(\base ? b, 10);
  ENDPROC
  PROC main()
    measure \b:=7;
    measure;
  ENDPROC
ENDMODULE
