MODULE dnum_division
! @format 2
! @section 3.12
! @expect ok
! @description Row / dnum / dnum -> dnum.
  VAR dnum a;
  VAR dnum b;
  VAR dnum r;
  PROC main()
    r := a / b;
  ENDPROC
ENDMODULE
