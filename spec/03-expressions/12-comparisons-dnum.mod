MODULE comparisons_dnum
! @format 2
! @section 3.12
! @expect ok
! @description Rows < <= >= > dnum, dnum -> bool.
  VAR dnum a;
  VAR dnum b;
  VAR bool r;
  PROC main()
    r := a < b;
    r := a <= b;
    r := a >= b;
    r := a > b;
  ENDPROC
ENDMODULE
