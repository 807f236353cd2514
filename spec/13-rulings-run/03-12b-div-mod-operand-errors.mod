MODULE rulings_div_mod_errors
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description R-3.12-b: DIV and MOD check the left operand, then the right one, then the divisor: a non-integer operand is ERR_NOTINTVAL, an integer outside num's exact sub-domain -8388607..8388608 is ERR_MAXINTVAL, a zero divisor ERR_DIVZERO; so 1.5 DIV 0 and 1.5 DIV 16777216 are ERR_NOTINTVAL, 16777216 DIV 0 and 16777216 DIV 1.5 ERR_MAXINTVAL. dnum operands must also not be negative (section 3.12, note c: ERR_NOTINTVAL) and are exact up to 4503599627370496.
! @output 7.5 DIV 2: ERR_NOTINTVAL
! @output 2 MOD 0.5: ERR_NOTINTVAL
! @output 7 DIV 0: ERR_DIVZERO
! @output 0 MOD 0: ERR_DIVZERO
! @output 16777216 DIV 2: ERR_MAXINTVAL
! @output 8388609 DIV 1: ERR_MAXINTVAL
! @output -8388608 MOD 2: ERR_MAXINTVAL
! @output 1.5 DIV 0: ERR_NOTINTVAL
! @output 16777216 DIV 0: ERR_MAXINTVAL
! @output 1.5 DIV 16777216: ERR_NOTINTVAL
! @output 16777216 DIV 1.5: ERR_MAXINTVAL
! @output 2 MOD 16777216: ERR_MAXINTVAL
! @output 8388608 MOD 8388608: 0
! @output dnum 7 DIV 2: 3
! @output dnum -7 DIV 2: ERR_NOTINTVAL
! @output dnum 7 MOD -2: ERR_NOTINTVAL
! @output dnum 2.5 DIV 1: ERR_NOTINTVAL
! @output dnum 9007199254740992 DIV 2: ERR_MAXINTVAL
! @output dnum 4503599627370497 MOD 2: ERR_MAXINTVAL
! @output dnum 7 MOD 0: ERR_DIVZERO
! @output dnum -1 DIV 0: ERR_NOTINTVAL
! @output dnum 9007199254740992 DIV -1: ERR_MAXINTVAL
! @exit 0
  FUNC string err_name()
    IF ERRNO = ERR_NOTINTVAL RETURN "ERR_NOTINTVAL";
    IF ERRNO = ERR_MAXINTVAL RETURN "ERR_MAXINTVAL";
    IF ERRNO = ERR_DIVZERO RETURN "ERR_DIVZERO";
    RETURN "another error";
  ENDFUNC

  PROC try_div(string label, num a, num b)
    TPWrite label + ": " \Num:=a DIV b;
  ERROR
    TPWrite label + ": " + err_name();
    RETURN;
  ENDPROC

  PROC try_mod(string label, num a, num b)
    TPWrite label + ": " \Num:=a MOD b;
  ERROR
    TPWrite label + ": " + err_name();
    RETURN;
  ENDPROC

  PROC try_ddiv(string label, dnum a, dnum b)
    TPWrite label + ": " \Dnum:=a DIV b;
  ERROR
    TPWrite label + ": " + err_name();
    RETURN;
  ENDPROC

  PROC try_dmod(string label, dnum a, dnum b)
    TPWrite label + ": " \Dnum:=a MOD b;
  ERROR
    TPWrite label + ": " + err_name();
    RETURN;
  ENDPROC

  PROC main()
    try_div "7.5 DIV 2", 7.5, 2;
    try_mod "2 MOD 0.5", 2, 0.5;
    try_div "7 DIV 0", 7, 0;
    try_mod "0 MOD 0", 0, 0;
    try_div "16777216 DIV 2", 16777216, 2;
    try_div "8388609 DIV 1", 8388609, 1;
    try_mod "-8388608 MOD 2", -8388608, 2;
    try_div "1.5 DIV 0", 1.5, 0;
    try_div "16777216 DIV 0", 16777216, 0;
    try_div "1.5 DIV 16777216", 1.5, 16777216;
    try_div "16777216 DIV 1.5", 16777216, 1.5;
    try_mod "2 MOD 16777216", 2, 16777216;
    try_mod "8388608 MOD 8388608", 8388608, 8388608;
    try_ddiv "dnum 7 DIV 2", 7, 2;
    try_ddiv "dnum -7 DIV 2", -7, 2;
    try_dmod "dnum 7 MOD -2", 7, -2;
    try_ddiv "dnum 2.5 DIV 1", 2.5, 1;
    try_ddiv "dnum 9007199254740992 DIV 2", 9007199254740992, 2;
    try_dmod "dnum 4503599627370497 MOD 2", 4503599627370497, 2;
    try_dmod "dnum 7 MOD 0", 7, 0;
    try_ddiv "dnum -1 DIV 0", -1, 0;
    try_ddiv "dnum 9007199254740992 DIV -1", 9007199254740992, -1;
  ENDPROC
ENDMODULE
