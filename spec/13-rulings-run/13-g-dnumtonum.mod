MODULE rulings_dnumtonum
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-g: DnumToNum rounds to single precision and is ERR_NUM_LIMIT beyond num's range; with \Integer a value that is not an integer is ERR_NOTINTVAL and an integer outside num's exact sub-domain -8388607..8388608 ERR_NUM_LIMIT.
! @output 0.1 = num 0.1 TRUE
! @output 16777217 = 16777216 TRUE
! @output \Integer 5=5
! @output \Integer 8388608=8388608
! @output \Integer -8388607=-8388607
! @output 1E39: ERR_NUM_LIMIT
! @output -1E39: ERR_NUM_LIMIT
! @output \Integer 2.5: ERR_NOTINTVAL
! @output \Integer 10000000: ERR_NUM_LIMIT
! @output \Integer 8388609: ERR_NUM_LIMIT
! @output \Integer -8388608: ERR_NUM_LIMIT
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_NUM_LIMIT RETURN "ERR_NUM_LIMIT";
    IF ERRNO = ERR_NOTINTVAL RETURN "ERR_NOTINTVAL";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR dnum d;
    VAR num x;
    d := 0.1;
    TPWrite "0.1 = num 0.1 " \Bool:=DnumToNum(d) = 0.1;
    d := 16777217;
    TPWrite "16777217 = 16777216 " \Bool:=DnumToNum(d) = 16777216;
    d := 5;
    TPWrite "\\Integer 5=" \Num:=DnumToNum(d \Integer);
    d := 8388608;
    TPWrite "\\Integer 8388608=" \Num:=DnumToNum(d \Integer);
    d := -8388607;
    TPWrite "\\Integer -8388607=" \Num:=DnumToNum(d \Integer);
    what := "1E39";
    d := 1E39;
    x := DnumToNum(d);
    what := "-1E39";
    d := -1E39;
    x := DnumToNum(d);
    what := "\\Integer 2.5";
    d := 2.5;
    x := DnumToNum(d \Integer);
    what := "\\Integer 10000000";
    d := 10000000;
    x := DnumToNum(d \Integer);
    what := "\\Integer 8388609";
    d := 8388609;
    x := DnumToNum(d \Integer);
    what := "\\Integer -8388608";
    d := -8388608;
    x := DnumToNum(d \Integer);
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
