MODULE dnum_div_and_mod
! @format 3
! @section 3.12
! @expect ok
! @description DIV and MOD of non-negative integer dnum values, beyond the integer range of num (section 3.12; dnum is exact up to 2^52, section 2.13).
! @output div=TRUE
! @output mod=TRUE
! @exit 0
  PROC main()
    VAR dnum a := 1000000000007;
    VAR dnum b := 1000;
    TPWrite "div=" \Bool:=a DIV b = 1000000000;
    TPWrite "mod=" \Bool:=a MOD b = 7;
  ENDPROC
ENDMODULE
