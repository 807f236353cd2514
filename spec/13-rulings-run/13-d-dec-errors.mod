MODULE rulings_round_dec_errors
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-d: the \Dec of Round, Trunc, RoundDnum and TruncDnum must be an integer (ERR_NOTINTVAL) and not negative (ERR_ARGVALERR).
! @output Round \Dec:=-1: ERR_ARGVALERR
! @output Round \Dec:=0.5: ERR_NOTINTVAL
! @output Trunc \Dec:=-2: ERR_ARGVALERR
! @output Trunc \Dec:=1.5: ERR_NOTINTVAL
! @output RoundDnum \Dec:=-1: ERR_ARGVALERR
! @output TruncDnum \Dec:=0.5: ERR_NOTINTVAL
! @output Round \Dec:=0=4
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_NOTINTVAL RETURN "ERR_NOTINTVAL";
    IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR num x;
    VAR dnum d := 3.75;
    what := "Round \\Dec:=-1";
    x := Round(3.75 \Dec:=-1);
    what := "Round \\Dec:=0.5";
    x := Round(3.75 \Dec:=0.5);
    what := "Trunc \\Dec:=-2";
    x := Trunc(3.75 \Dec:=-2);
    what := "Trunc \\Dec:=1.5";
    x := Trunc(3.75 \Dec:=1.5);
    what := "RoundDnum \\Dec:=-1";
    d := RoundDnum(d \Dec:=-1);
    what := "TruncDnum \\Dec:=0.5";
    d := TruncDnum(d \Dec:=0.5);
    TPWrite "Round \\Dec:=0=" \Num:=Round(3.75 \Dec:=0);
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
