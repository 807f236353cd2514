MODULE rulings_results_single
! @format 3
! @section 2.13
! @expect ok
! @description R-2.13-a: every num result is rounded to single precision and a dnum result is a double: the integers are exact up to 8388608 for num and far beyond for dnum, 16777216 + 1 is 16777216 for num and 16777217 for dnum.
! @output num 8388607 + 1 = 8388608
! @output num 16777216 + 1 = 16777216 TRUE
! @output dnum 16777216 + 1 = 16777217
! @output dnum 4503599627370495 + 1 = 4503599627370496
! @exit 0
  PROC main()
    VAR num a := 8388607;
    VAR num b := 16777216;
    VAR dnum c := 16777216;
    VAR dnum e := 4503599627370495;
    TPWrite "num 8388607 + 1 = " \Num:=a + 1;
    TPWrite "num 16777216 + 1 = 16777216 " \Bool:=b + 1 = b;
    TPWrite "dnum 16777216 + 1 = " \Dnum:=c + 1;
    TPWrite "dnum 4503599627370495 + 1 = " \Dnum:=e + 1;
  ENDPROC
ENDMODULE
