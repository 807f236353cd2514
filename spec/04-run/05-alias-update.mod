MODULE alias_update
! @format 3
! @section 3.1
! @section 3.12
! @section 5.2
! @expect ok
! @description x := x + y and x := x - y on an INOUT, VAR or PERS parameter: the parameter's value is read where it is bound before y is evaluated (a function that changes the bound data meanwhile does not change the left operand); the sum is rounded to single (16777216 + 1 is 16777216); an infinite result is ERR_OVERFLOW and leaves the data as it was.
! @output 3 -2 2
! @output 11 10
! @output 16777216
! @output handled 1120
! @output kept 3E+38
! @exit 0
  VAR num g := 1;
  PERS num pcount := 0;
  FUNC num bump()
    g := 100;
    RETURN 10;
  ENDFUNC
  PROC count_up(INOUT num b, VAR num c, PERS num d, num k)
    b := b + k;
    c := c - k;
    d := d + 1;
  ENDPROC
  PROC later(INOUT num b)
    b := b + bump();
  ENDPROC
  PROC add(INOUT num b, num k)
    b := b + k;
  ENDPROC
  PROC main()
    VAR num b := 1;
    VAR num c := 0;
    VAR num big := 16777216;
    VAR num huge := 3E+38;
    count_up b, c, pcount, 1;
    count_up b, c, pcount, 1;
    TPWrite NumToStr(b, 0) + " " + NumToStr(c, 0) + " " + NumToStr(pcount, 0);
    later g;
    TPWrite NumToStr(g, 0) + " " + NumToStr(bump(), 0);
    add big, 1;
    TPWrite NumToStr(big, 0);
    add huge, 3E+38;
    TPWrite "kept " \Num:=huge;
  ERROR
    TPWrite "handled " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
