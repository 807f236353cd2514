MODULE round_use
! @format 3
! @section 13
! @expect ok
! @description Round rounds to the nearest integer, or to Dec decimals (installed-facts.md section 1: Round(0.3852138\Dec:=3) is 0.385, \Dec:=1 gives 0.4, no Dec gives 0).
! @output TRUE
! @output TRUE
! @output 0
! @output 3
! @output -3
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(Round(0.3852138\Dec:=3) - 0.385) < 0.00001;
    TPWrite "" \Bool:=Abs(Round(0.3852138\Dec:=1) - 0.4) < 0.00001;
    TPWrite "" \Num:=Round(0.3852138);
    TPWrite "" \Num:=Round(2.6);
    TPWrite "" \Num:=Round(-2.6);
  ENDPROC
ENDMODULE
