MODULE strtoval_use
! @format 3
! @section 13
! @expect ok
! @description StrToVal converts text to a value of its second argument's type and returns TRUE, or FALSE when the text is no such value (installed-facts.md section 1: StrToVal("3.85",nval)).
! @output ok=TRUE near=TRUE
! @output pos ok=TRUE equal=TRUE
! @output bool ok=TRUE value=TRUE
! @output bad=FALSE
! @exit 0
  PROC main()
    VAR num nval;
    VAR pos pval;
    VAR bool bval;
    VAR bool ok;
    ok := StrToVal("3.85", nval);
    TPWrite "ok=" + ValToStr(ok) + " near=" + ValToStr(Abs(nval - 3.85) < 0.0001);
    ok := StrToVal("[1,2,3]", pval);
    TPWrite "pos ok=" + ValToStr(ok) + " equal=" + ValToStr(pval = [1, 2, 3]);
    ok := StrToVal("TRUE", bval);
    TPWrite "bool ok=" + ValToStr(ok) + " value=" + ValToStr(bval);
    TPWrite "bad=" \Bool:=StrToVal("abc", nval);
  ENDPROC
ENDMODULE
