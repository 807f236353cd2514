MODULE num_literal_rounding
! @format 3
! @section 2.5
! @section 2.13
! @expect ok
! @description Literals are rounded to the type of their context and results to single precision: 0.1 + 0.2 = 0.3 holds for num (all three rounded to single precision) but not for dnum (double precision).
! @output num=TRUE
! @output dnum=FALSE
! @exit 0
  PROC main()
    VAR num a := 0.1;
    VAR num b := 0.2;
    VAR dnum c := 0.1;
    VAR dnum d := 0.2;
    TPWrite "num=" \Bool:=a + b = 0.3;
    TPWrite "dnum=" \Bool:=c + d = 0.3;
  ENDPROC
ENDMODULE
