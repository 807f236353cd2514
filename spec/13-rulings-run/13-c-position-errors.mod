MODULE rulings_string_position_errors
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-c: StrPart needs ChPos >= 1, Len >= 0 and ChPos + Len - 1 <= StrLen; StrFind and StrMatch start at 1..StrLen+1; StrMemb needs ChPos in 1..StrLen; otherwise ERR_OUTOFBND. A position or length that is not an integer is ERR_NOTINTVAL.
! @output StrPart(s,8,2): ERR_OUTOFBND
! @output StrPart(s,0,1): ERR_OUTOFBND
! @output StrPart(s,1,-1): ERR_OUTOFBND
! @output StrPart(s,10,0): ERR_OUTOFBND
! @output StrPart(s,1.5,1): ERR_NOTINTVAL
! @output StrPart(s,1,1.5): ERR_NOTINTVAL
! @output StrFind(s,10,...): ERR_OUTOFBND
! @output StrFind(s,0,...): ERR_OUTOFBND
! @output StrFind(s,1.5,...): ERR_NOTINTVAL
! @output StrMatch(s,10,...): ERR_OUTOFBND
! @output StrMemb(s,9,...): ERR_OUTOFBND
! @output StrMemb(s,0,...): ERR_OUTOFBND
! @exit 0
  VAR string what;

  FUNC string err_name()
    IF ERRNO = ERR_OUTOFBND RETURN "ERR_OUTOFBND";
    IF ERRNO = ERR_NOTINTVAL RETURN "ERR_NOTINTVAL";
    RETURN "another error";
  ENDFUNC

  PROC main()
    VAR string s := "Robotics";
    VAR string t;
    VAR num n;
    VAR bool b;
    what := "StrPart(s,8,2)";
    t := StrPart(s, 8, 2);
    what := "StrPart(s,0,1)";
    t := StrPart(s, 0, 1);
    what := "StrPart(s,1,-1)";
    t := StrPart(s, 1, -1);
    what := "StrPart(s,10,0)";
    t := StrPart(s, 10, 0);
    what := "StrPart(s,1.5,1)";
    t := StrPart(s, 1.5, 1);
    what := "StrPart(s,1,1.5)";
    t := StrPart(s, 1, 1.5);
    what := "StrFind(s,10,...)";
    n := StrFind(s, 10, "s");
    what := "StrFind(s,0,...)";
    n := StrFind(s, 0, "s");
    what := "StrFind(s,1.5,...)";
    n := StrFind(s, 1.5, "s");
    what := "StrMatch(s,10,...)";
    n := StrMatch(s, 10, "s");
    what := "StrMemb(s,9,...)";
    b := StrMemb(s, 9, "aeiou");
    what := "StrMemb(s,0,...)";
    b := StrMemb(s, 0, "aeiou");
  ERROR
    TPWrite what + ": " + err_name();
    TRYNEXT;
  ENDPROC
ENDMODULE
