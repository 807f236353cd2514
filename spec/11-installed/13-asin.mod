MODULE asin_use
! @format 3
! @section 13
! @expect ok
! @description ASin gives an angle in degrees, from -90 to 90 (installed-facts.md section 1: degrees, the reading consistent with Sin).
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(ASin(0.5) - 30) < 0.001;
    TPWrite "" \Bool:=Abs(ASin(-1) + 90) < 0.001;
  ENDPROC
ENDMODULE
