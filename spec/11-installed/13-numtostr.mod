MODULE numtostr_use
! @format 3
! @section 13
! @expect ok
! @description NumToStr(Val, Dec) writes Val rounded to Dec decimals (installed-facts.md section 1: NumToStr(0.38521,3) is "0.385").
! @output 0.385
! @output 7
! @output 1.50
! @output -3.14
! @exit 0
  PROC main()
    TPWrite NumToStr(0.38521, 3);
    TPWrite NumToStr(7, 0);
    TPWrite NumToStr(1.5, 2);
    TPWrite NumToStr(-3.14159, 2);
  ENDPROC
ENDMODULE
