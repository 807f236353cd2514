MODULE rulings_strtoval_reads
! @format 3
! @section 13
! @section 2.5
! @expect ok
! @description R-13-b: StrToVal reads the texts of values of Val's type in the literal syntax of sections 2.5-2.7: numbers with a sign in decimal, 0x, 0o and 0b forms, TRUE/FALSE in any letter case, a quoted string, an aggregate with the right number of components, blanks around each item; StrToVal of ValToStr gives a string back.
! @output 0x1F TRUE 31
! @output 0b101 TRUE 5
! @output 0o17 TRUE 15
! @output -2.5E-3 TRUE TRUE
! @output true TRUE TRUE
! @output fAlSe TRUE FALSE
! @output string TRUE 3 TRUE
! @output pos TRUE [1,2,3]
! @output dnum 1E39 TRUE TRUE
! @output back TRUE TRUE
! @exit 0
  PROC main()
    VAR num n;
    VAR bool flag;
    VAR string s;
    VAR pos p;
    VAR dnum d;
    VAR string original := "q""\\\07 x";
    VAR bool ok;
    ok := StrToVal("0x1F", n);
    TPWrite "0x1F " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("0b101", n);
    TPWrite "0b101 " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("0o17", n);
    TPWrite "0o17 " + ValToStr(ok) + " " \Num:=n;
    ok := StrToVal("  -2.5E-3 ", n);
    TPWrite "-2.5E-3 " + ValToStr(ok) + " " \Bool:=n = -2.5E-3;
    ok := StrToVal("true", flag);
    TPWrite "true " + ValToStr(ok) + " " \Bool:=flag;
    flag := TRUE;
    ok := StrToVal(" fAlSe", flag);
    TPWrite "fAlSe " + ValToStr(ok) + " " \Bool:=flag;
    ok := StrToVal("""a""""b""", s);
    TPWrite "string " + ValToStr(ok) + " " + ValToStr(StrLen(s)) + " " \Bool:=s = "a""b";
    ok := StrToVal("[ 1 , 2 , 3 ]", p);
    TPWrite "pos " + ValToStr(ok) + " " \Pos:=p;
    ok := StrToVal("1E39", d);
    TPWrite "dnum 1E39 " + ValToStr(ok) + " " \Bool:=d > 1E38;
    ok := StrToVal(ValToStr(original), s);
    TPWrite "back " + ValToStr(ok) + " " \Bool:=s = original;
  ENDPROC
ENDMODULE
