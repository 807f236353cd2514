MODULE strorder_use
! @format 3
! @section 13
! @expect ok
! @description StrOrder tells whether Str1 sorts before Str2 under the character order Order; a prefix sorts first (installed-facts.md section 1's three examples).
! @output TRUE
! @output TRUE
! @output FALSE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=StrOrder("FIRST", "SECOND", STR_UPPER);
    TPWrite "" \Bool:=StrOrder("FIRST", "FIRSTB", STR_UPPER);
    TPWrite "" \Bool:=StrOrder("FIRSTB", "FIRST", STR_UPPER);
  ENDPROC
ENDMODULE
