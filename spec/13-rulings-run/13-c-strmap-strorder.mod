MODULE rulings_strmap_strorder
! @format 3
! @section 13
! @expect ok
! @description R-13-c: StrMap maps a byte by its first occurrence in FromMap and keeps one whose place is past the end of ToMap; StrOrder ranks bytes by their first place in Order, bytes not in Order after all of Order and among themselves by code, a proper prefix first, and equal strings give FALSE.
! @output RObOtics
! @output xbc
! @output ROBOTICS 2
! @output equal FALSE
! @output prefix TRUE
! @output longer FALSE
! @output empty first TRUE
! @output by Order TRUE
! @output not in Order after it FALSE
! @output in Order before the others TRUE
! @output others by code TRUE
! @output others by code, reversed FALSE
! @exit 0
  PROC main()
    TPWrite StrMap("Robotics", "oi", "O");
    TPWrite StrMap("abc", "aa", "xy");
    TPWrite StrMap("Robotics 2", STR_LOWER, STR_UPPER);
    TPWrite "equal " \Bool:=StrOrder("AB", "AB", STR_UPPER);
    TPWrite "prefix " \Bool:=StrOrder("FIRST", "FIRSTB", STR_UPPER);
    TPWrite "longer " \Bool:=StrOrder("FIRSTB", "FIRST", STR_UPPER);
    TPWrite "empty first " \Bool:=StrOrder("", "A", STR_UPPER);
    TPWrite "by Order " \Bool:=StrOrder("B", "A", "BA");
    TPWrite "not in Order after it " \Bool:=StrOrder("A1", "AB", STR_UPPER);
    TPWrite "in Order before the others " \Bool:=StrOrder("AB", "A1", STR_UPPER);
    TPWrite "others by code " \Bool:=StrOrder("1", "2", STR_UPPER);
    TPWrite "others by code, reversed " \Bool:=StrOrder("b", "a", STR_UPPER);
  ENDPROC
ENDMODULE
