MODULE rulings_dnum_text
! @format 3
! @section 13
! @expect ok
! @description R-13-a: TPWrite \Dnum and ValToStr write a dnum that is an integer of the exact sub-domain in full, any other with 15 significant digits, positional for decimal exponents -4..14 and d.ddddE+XX otherwise, trailing zeros removed.
! @output 1/3=0.333333333333333
! @output 2/3=0.666666666666667
! @output 2^52=4503599627370496
! @output -2^52=-4503599627370496
! @output 12345678901234567=1.23456789012346E+16
! @output 0.1=0.1
! @output 123456789.125=123456789.125
! @output 0.00001=1E-05
! @output 0.0001=0.0001
! @output 0.333333333333333
! @exit 0
  PROC main()
    VAR dnum one := 1;
    VAR dnum two := 2;
    VAR dnum three := 3;
    VAR dnum top := 4503599627370496;
    VAR dnum big := 12345678901234567;
    VAR dnum tenth := 0.1;
    VAR dnum frac := 123456789.125;
    VAR dnum small := 0.00001;
    VAR dnum small4 := 0.0001;
    TPWrite "1/3=" \Dnum:=one / three;
    TPWrite "2/3=" \Dnum:=two / three;
    TPWrite "2^52=" \Dnum:=top;
    TPWrite "-2^52=" \Dnum:=-top;
    TPWrite "12345678901234567=" \Dnum:=big;
    TPWrite "0.1=" \Dnum:=tenth;
    TPWrite "123456789.125=" \Dnum:=frac;
    TPWrite "0.00001=" \Dnum:=small;
    TPWrite "0.0001=" \Dnum:=small4;
    TPWrite ValToStr(one / three);
  ENDPROC
ENDMODULE
