MODULE rulings_bit_errors
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-h: a byte operand must be an integer (ERR_NOTINTVAL) in 0..255, a dnum one in 0..2^52-1, a bit position in 1..8 (1..52 for dnum) and a shift count not negative; otherwise ERR_ARGVALERR.
! @output BitAnd(256,1): ERR_ARGVALERR
! @output BitAnd(-1,1): ERR_ARGVALERR
! @output BitOr(1.5,1): ERR_NOTINTVAL
! @output BitCheck(1,9): ERR_ARGVALERR
! @output BitCheck(1,0): ERR_ARGVALERR
! @output BitLSh(1,-1): ERR_ARGVALERR
! @output BitNegDnum(0.5): ERR_NOTINTVAL
! @output BitAndDnum(2^52,1): ERR_ARGVALERR
! @output BitCheckDnum(1,53): ERR_ARGVALERR
! @output BitLSh(1,100)=0
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    IF ERRNO = ERR_NOTINTVAL RETURN "ERR_NOTINTVAL";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR num x;
    VAR bool f;
    VAR dnum half := 0.5;
    VAR dnum big := 4503599627370496;
    VAR dnum one := 1;
    VAR dnum d;
    what := "BitAnd(256,1)";
    x := BitAnd(256, 1);
    what := "BitAnd(-1,1)";
    x := BitAnd(-1, 1);
    what := "BitOr(1.5,1)";
    x := BitOr(1.5, 1);
    what := "BitCheck(1,9)";
    f := BitCheck(1, 9);
    what := "BitCheck(1,0)";
    f := BitCheck(1, 0);
    what := "BitLSh(1,-1)";
    x := BitLSh(1, -1);
    what := "BitNegDnum(0.5)";
    d := BitNegDnum(half);
    what := "BitAndDnum(2^52,1)";
    d := BitAndDnum(big, one);
    what := "BitCheckDnum(1,53)";
    f := BitCheckDnum(one, 53);
    TPWrite "BitLSh(1,100)=" \Num:=BitLSh(1, 100);
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
