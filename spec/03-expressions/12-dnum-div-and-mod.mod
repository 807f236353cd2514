MODULE dnum_div_and_mod
! @format 2
! @section 3.12
! @expect ok
! @description Rows DIV and MOD dnum, dnum -> dnum.
  VAR dnum a;
  VAR dnum b;
  VAR dnum r;
  CONST dnum four := 4;
  CONST dnum two := 2;
  PROC main()
    r := a DIV b;
    r := a MOD b;
    r := four DIV two + four MOD two;
  ENDPROC
ENDMODULE
