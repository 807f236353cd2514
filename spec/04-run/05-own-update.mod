MODULE own_update
! @format 3
! @section 3.1
! @section 3.12
! @section 2.13
! @expect ok
! @description x := x + y and x := x - y on routine data (num and dnum): x is read before y is evaluated (a function that changes x through an INOUT parameter meanwhile does not change the left operand); a num sum is rounded to single (16777216 + 1 is 16777216); a dnum sum is exact in double precision (9007199254740992 - 1); an infinite result is ERR_OVERFLOW and leaves x as it was.
! @output 11 100
! @output 16777216 9007199254740991
! @output handled 1120
! @output handled 1120
! @output kept 3E+38 1.0E+308
! @output 1.5 -2.5
! @exit 0
  FUNC num bump(INOUT num b)
    b := 100;
    RETURN 10;
  ENDFUNC
  PROC main()
    VAR num x := 1;
    VAR num y := 0;
    VAR num big := 16777216;
    VAR dnum d := 9007199254740992;
    VAR num huge := 3E+38;
    VAR dnum dhuge := 1E+308;
    VAR num h := 1;
    VAR dnum e := 0;
    x := x + bump(y);
    y := y - 0;
    TPWrite NumToStr(x, 0) + " " + NumToStr(y, 0);
    big := big + 1;
    d := d - 1;
    TPWrite NumToStr(big, 0) + " " + DnumToStr(d, 0);
    huge := huge + 3E+38;
    dhuge := dhuge + 1E+308;
    TPWrite "kept " + NumToStr(huge, 0\Exp) + " " + DnumToStr(dhuge, 1\Exp);
    h := h + 0.5;
    e := e - 2.5;
    TPWrite NumToStr(h, 1) + " " + DnumToStr(e, 1);
  ERROR
    TPWrite "handled " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
