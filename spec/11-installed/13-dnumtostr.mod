MODULE dnumtostr_use
! @format 3
! @section 13
! @expect ok
! @description DnumToStr(Val, Dec) is NumToStr for dnum: an integer beyond the exact range of num is written exactly.
! @output 12345678901
! @output 0.250
! @exit 0
  PROC main()
    VAR dnum big := 12345678901;
    VAR dnum quarter := 0.25;
    TPWrite DnumToStr(big, 0);
    TPWrite DnumToStr(quarter, 3);
  ENDPROC
ENDMODULE
