MODULE rulings_div_mod_truncate
! @format 3
! @section 3.12
! @expect ok
! @description R-3.12-b (and R-3.12): DIV and MOD truncate toward zero, the remainder takes the sign of the dividend, and the whole integer sub-domain of num (-8388607..8388608) and of dnum (0..4503599627370496) is allowed.
! @output -7 DIV 2 = -3, -7 MOD 2 = -1
! @output 7 DIV -2 = -3, 7 MOD -2 = 1
! @output -7 DIV -2 = 3, -7 MOD -2 = -1
! @output -1 DIV 2 = 0, -4 MOD 2 = 0
! @output 8388608 DIV 2 = 4194304, -8388607 MOD 10 = -7
! @output dnum 4503599627370496 DIV 1 = 4503599627370496
! @output dnum 4503599627370496 MOD 3 = 1
! @exit 0
  PROC show(string label, num a, num b)
    TPWrite label + " DIV " + NumToStr(b, 0) + " = " + NumToStr(a DIV b, 0) + ", " + label + " MOD " + NumToStr(b, 0) + " = " + NumToStr(a MOD b, 0);
  ENDPROC

  PROC main()
    VAR dnum top := 4503599627370496;
    VAR dnum one := 1;
    VAR dnum three := 3;
    show "-7", -7, 2;
    show "7", 7, -2;
    show "-7", -7, -2;
    TPWrite "-1 DIV 2 = " + ValToStr(-1 DIV 2) + ", -4 MOD 2 = " + ValToStr(-4 MOD 2);
    TPWrite "8388608 DIV 2 = " + ValToStr(8388608 DIV 2) + ", -8388607 MOD 10 = " + ValToStr(-8388607 MOD 10);
    TPWrite "dnum 4503599627370496 DIV 1 = " \Dnum:=top DIV one;
    TPWrite "dnum 4503599627370496 MOD 3 = " \Dnum:=top MOD three;
  ENDPROC
ENDMODULE
