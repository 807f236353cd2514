MODULE rulings_math_errors
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-e and R-3.12-c: Sqrt of a negative number, ASin or ACos outside [-1, 1] and Pow of a negative base to a non-integer exponent are ERR_ARGVALERR; an infinite result (Exp(100), Tan(90), Pow(0,-1)) is ERR_OVERFLOW; a negative base with an integer exponent is allowed.
! @output Sqrt(-1): ERR_ARGVALERR
! @output SqrtDnum(-1): ERR_ARGVALERR
! @output ASin(1.5): ERR_ARGVALERR
! @output ACos(-1.5): ERR_ARGVALERR
! @output Pow(-8,0.5): ERR_ARGVALERR
! @output Exp(100): ERR_OVERFLOW
! @output Tan(90): ERR_OVERFLOW
! @output Tan(-270): ERR_OVERFLOW
! @output Pow(0,-1): ERR_OVERFLOW
! @output Pow(-2,3)=-8
! @output Sqrt(0)=0
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    IF ERRNO = ERR_OVERFLOW RETURN "ERR_OVERFLOW";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR num x;
    VAR dnum d := -1;
    what := "Sqrt(-1)";
    x := Sqrt(-1);
    what := "SqrtDnum(-1)";
    d := SqrtDnum(d);
    what := "ASin(1.5)";
    x := ASin(1.5);
    what := "ACos(-1.5)";
    x := ACos(-1.5);
    what := "Pow(-8,0.5)";
    x := Pow(-8, 0.5);
    what := "Exp(100)";
    x := Exp(100);
    what := "Tan(90)";
    x := Tan(90);
    what := "Tan(-270)";
    x := Tan(-270);
    what := "Pow(0,-1)";
    x := Pow(0, -1);
    TPWrite "Pow(-2,3)=" \Num:=Pow(-2, 3);
    TPWrite "Sqrt(0)=" \Num:=Sqrt(0);
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
