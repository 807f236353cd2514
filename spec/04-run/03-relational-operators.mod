MODULE relational_operators
! @format 3
! @section 3.12
! @expect ok
! @description The relational operators on num and dnum (section 3.12).
! @output TRUE
! @output TRUE
! @output FALSE
! @output TRUE
! @output TRUE
! @output FALSE
! @output TRUE
! @exit 0
  PROC main()
    VAR num a := 2;
    VAR num b := 3;
    VAR dnum c := 5000000000;
    VAR dnum d := 5000000001;
    TPWrite "" \Bool:=a < b;
    TPWrite "" \Bool:=a <= a;
    TPWrite "" \Bool:=a > b;
    TPWrite "" \Bool:=b >= a;
    TPWrite "" \Bool:=a <> b;
    TPWrite "" \Bool:=c = d;
    TPWrite "" \Bool:=c < d;
  ENDPROC
ENDMODULE
