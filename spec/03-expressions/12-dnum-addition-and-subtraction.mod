MODULE dnum_addition_and_subtraction
! @format 2
! @section 3.12
! @expect ok
! @description Rows + and - dnum, dnum -> dnum (the extraction prints the + row as dnum + num; restored from the - row).
  VAR dnum a;
  VAR dnum b;
  VAR dnum r;
  PROC main()
    r := a + b;
    r := a - b;
  ENDPROC
ENDMODULE
