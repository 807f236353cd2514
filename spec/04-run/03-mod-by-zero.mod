MODULE mod_by_zero
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description MOD by zero raises ERR_DIVZERO, like / and DIV (section 3.12, chapter 12).
! @exit 1
! @error ERR_DIVZERO 12:5
  PROC main()
    VAR num d := 0;
    VAR num x;
    x := 7 MOD d;
  ENDPROC
ENDMODULE
