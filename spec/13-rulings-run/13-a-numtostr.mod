MODULE rulings_numtostr
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-a: NumToStr and DnumToStr write exactly Dec decimals (no point when Dec is 0), rounding the exact binary value to nearest with ties away from zero (0.125 gives 0.13, 2.5 gives 3, 1.005 gives 1.00 because the single nearest 1.005 is below it), no minus sign on a value rounded to zero; with \Exp one digit, the point, Dec decimals, E, a sign and two or more exponent digits. Dec must be an integer (ERR_NOTINTVAL) and not negative (ERR_ARGVALERR); more than 80 bytes is ERR_STRTOOLNG.
! @output 0.385
! @output 0.13
! @output -0.13
! @output 1.00
! @output 3
! @output -3
! @output 1
! @output 0.00
! @output 7.00
! @output 123456792
! @output 0.1000000015
! @output 0.10000000000000000555
! @output 0.13
! @output 4503599627370496
! @output 3.85E-01
! @output 1.235E+03
! @output -1.23E-04
! @output 1.0E+20
! @output 1.00E+01
! @output 0.00E+00
! @output 1.00E+300
! @output Dec 0.5: ERR_NOTINTVAL
! @output Dec -1: ERR_ARGVALERR
! @output dnum Dec -1: ERR_ARGVALERR
! @output 78 decimals=80
! @output 79 decimals: ERR_STRTOOLNG
! @output \Exp 74 decimals=80
! @output \Exp 75 decimals: ERR_STRTOOLNG
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_NOTINTVAL RETURN "ERR_NOTINTVAL";
    IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    IF ERRNO = ERR_STRTOOLNG RETURN "ERR_STRTOOLNG";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR dnum tenth := 0.1;
    VAR dnum eighth := 0.125;
    VAR dnum top := 4503599627370496;
    VAR dnum big := 1E300;
    VAR dnum one := 1;
    VAR string s;
    TPWrite NumToStr(0.38521, 3);
    TPWrite NumToStr(0.125, 2);
    TPWrite NumToStr(-0.125, 2);
    TPWrite NumToStr(1.005, 2);
    TPWrite NumToStr(2.5, 0);
    TPWrite NumToStr(-2.5, 0);
    TPWrite NumToStr(0.5, 0);
    TPWrite NumToStr(-0.001, 2);
    TPWrite NumToStr(7, 2);
    TPWrite NumToStr(123456789, 0);
    TPWrite NumToStr(0.1, 10);
    TPWrite DnumToStr(tenth, 20);
    TPWrite DnumToStr(eighth, 2);
    TPWrite DnumToStr(top, 0);
    TPWrite NumToStr(0.38521, 2 \Exp);
    TPWrite NumToStr(1234.5, 3 \Exp);
    TPWrite NumToStr(-0.000123, 2 \Exp);
    TPWrite NumToStr(1E20, 1 \Exp);
    TPWrite NumToStr(9.999, 2 \Exp);
    TPWrite NumToStr(0, 2 \Exp);
    TPWrite DnumToStr(big, 2 \Exp);
    what := "Dec 0.5";
    s := NumToStr(1, 0.5);
    what := "Dec -1";
    s := NumToStr(1, -1);
    what := "dnum Dec -1";
    s := DnumToStr(one, -1);
    s := NumToStr(1, 78);
    TPWrite "78 decimals=" \Num:=StrLen(s);
    what := "79 decimals";
    s := NumToStr(1, 79);
    s := NumToStr(1, 74 \Exp);
    TPWrite "\\Exp 74 decimals=" \Num:=StrLen(s);
    what := "\\Exp 75 decimals";
    s := NumToStr(1, 75 \Exp);
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
