MODULE dnum_division_by_zero
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description Division of dnum values by zero raises ERR_DIVZERO too.
! @exit 1
! @error ERR_DIVZERO 12:5
  PROC main()
    VAR dnum d := 0;
    VAR dnum x;
    x := 5 / d;
  ENDPROC
ENDMODULE
