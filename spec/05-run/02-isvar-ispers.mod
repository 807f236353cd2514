MODULE isvar_ispers
! @format 3
! @section 5.2
! @section 11
! @expect ok
! @description IsVar and IsPers tell whether an inout parameter is an alias of a variable or of a persistent (section 5.2, chapter 11).
! @output var: IsVar=TRUE IsPers=FALSE
! @output pers: IsVar=FALSE IsPers=TRUE
! @exit 0
  VAR num v;
  PERS num p := 0;
  PROC which(string label, INOUT num x)
    TPWrite label + ": IsVar=" + ValToStr(IsVar(x)) + " IsPers=" + ValToStr(IsPers(x));
  ENDPROC
  PROC main()
    which "var", v;
    which "pers", p;
  ENDPROC
ENDMODULE
