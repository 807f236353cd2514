MODULE rulings_gradual_underflow
! @format 3
! @section 3.12
! @expect ok
! @description R-3.12-c: underflow is gradual, as in IEEE 754, and no error: 1E-38 / 1E6 is a subnormal single, 1E-38 / 1E10 is 0 for num but a double for dnum, and 1E-300 / 1E10 a subnormal double.
! @output num 1E-38 / 1E6 > 0 TRUE
! @output num 1E-38 / 1E10 = 0 TRUE
! @output dnum 1E-38 / 1E10 > 0 TRUE
! @output dnum 1E-300 / 1E10 > 0 TRUE
! @output dnum 1E-300 / 1E100 = 0 TRUE
! @exit 0
  PROC main()
    VAR num small := 1E-38;
    VAR dnum dsmall := 1E-38;
    VAR dnum dtiny := 1E-300;
    VAR num x;
    VAR dnum d;
    x := small / 1E6;
    TPWrite "num 1E-38 / 1E6 > 0 " \Bool:=x > 0;
    x := small / 1E10;
    TPWrite "num 1E-38 / 1E10 = 0 " \Bool:=x = 0;
    d := dsmall / 1E10;
    TPWrite "dnum 1E-38 / 1E10 > 0 " \Bool:=d > 0;
    d := dtiny / 1E10;
    TPWrite "dnum 1E-300 / 1E10 > 0 " \Bool:=d > 0;
    d := dtiny / 1E100;
    TPWrite "dnum 1E-300 / 1E100 = 0 " \Bool:=d = 0;
  ENDPROC
ENDMODULE
