MODULE rulings_operator_errors
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description R-3.12-c: no operator yields an infinity or a NaN: num, dnum and pos results beyond the largest finite number of their precision are ERR_OVERFLOW, / by zero (0 / 0 included, num, dnum and pos / num) is ERR_DIVZERO, a concatenation of more than 80 bytes ERR_STRTOOLNG; a result of exactly 80 bytes is allowed.
! @output num + num: ERR_OVERFLOW
! @output -num - num: ERR_OVERFLOW
! @output dnum * dnum: ERR_OVERFLOW
! @output pos * num: ERR_OVERFLOW
! @output num * pos: ERR_OVERFLOW
! @output pos + pos: ERR_OVERFLOW
! @output 1 / 0: ERR_DIVZERO
! @output 0 / 0: ERR_DIVZERO
! @output dnum / 0: ERR_DIVZERO
! @output pos / 0: ERR_DIVZERO
! @output 81 bytes: ERR_STRTOOLNG
! @output 80 bytes=80
! @output x unchanged=1
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_OVERFLOW RETURN "ERR_OVERFLOW";
    IF ERRNO = ERR_DIVZERO RETURN "ERR_DIVZERO";
    IF ERRNO = ERR_STRTOOLNG RETURN "ERR_STRTOOLNG";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR num big := 3.4E38;
    VAR num zero := 0;
    VAR dnum dbig := 1E300;
    VAR dnum dzero := 0;
    VAR pos p := [1E38, 0, 0];
    VAR pos r := [3E38, 0, 0];
    VAR string s40 := "0123456789012345678901234567890123456789";
    VAR num x := 1;
    VAR dnum d;
    VAR pos q;
    VAR string s;
    what := "num + num";
    x := big + big;
    what := "-num - num";
    x := -big - big;
    what := "dnum * dnum";
    d := dbig * dbig;
    what := "pos * num";
    q := p * 10;
    what := "num * pos";
    q := 10 * p;
    what := "pos + pos";
    q := r + r;
    what := "1 / 0";
    x := 1 / zero;
    what := "0 / 0";
    x := zero / zero;
    what := "dnum / 0";
    d := dbig / dzero;
    what := "pos / 0";
    q := p / zero;
    what := "81 bytes";
    s := s40 + s40 + "x";
    s := s40 + s40;
    TPWrite "80 bytes=" \Num:=StrLen(s);
    TPWrite "x unchanged=" \Num:=x;
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
