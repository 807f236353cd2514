MODULE rulings_strtoval_refuses
! @format 3
! @section 13
! @expect ok
! @description R-13-b: anything that is not the text of a value of Val's type gives FALSE and leaves Val unchanged: words, trailing text, an exponent without digits, a number num cannot hold (1E39), a string without quotes, an aggregate with too few or too many components.
! @output abc FALSE 7
! @output 12abc FALSE 7
! @output 2E FALSE 7
! @output 1.5.2 FALSE 7
! @output empty FALSE 7
! @output 1E39 FALSE 7
! @output yes FALSE TRUE
! @output unquoted FALSE keep
! @output [1,2] FALSE [4,5,6]
! @output [1,2,3,4] FALSE [4,5,6]
! @exit 0
  PROC main()
    VAR num n := 7;
    VAR bool flag := TRUE;
    VAR string s := "keep";
    VAR pos p := [4, 5, 6];
    VAR bool ok;
    ok := StrToVal("abc", n);
    TPWrite "abc " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("12abc", n);
    TPWrite "12abc " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("2E", n);
    TPWrite "2E " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("1.5.2", n);
    TPWrite "1.5.2 " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("", n);
    TPWrite "empty " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("1E39", n);
    TPWrite "1E39 " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("yes", flag);
    TPWrite "yes " + ValToStr(ok) + " " \Bool:=flag;
    ok := StrToVal("abc", s);
    TPWrite "unquoted " + ValToStr(ok) + " " + s;
    ok := StrToVal("[1,2]", p);
    TPWrite "[1,2] " + ValToStr(ok) + " " \Pos:=p;
    ok := StrToVal("[1,2,3,4]", p);
    TPWrite "[1,2,3,4] " + ValToStr(ok) + " " \Pos:=p;
  ENDPROC
ENDMODULE
