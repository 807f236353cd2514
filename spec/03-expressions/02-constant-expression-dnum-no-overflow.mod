MODULE constant_dnum_no_overflow
! @format 2
! @section 3.2
! @section 2.13
! @expect ok
! @description The same product in a dnum constant is within double precision: accepted.
  CONST dnum large := 3E38;
  CONST dnum twice := large * 2;
  CONST num fits := 3E38 * 1.1;
  PROC main()
  ENDPROC
ENDMODULE
