MODULE persistent_keeps_value
! @format 3
! @section 2.21
! @section 2.23
! @expect ok
! @description Persistents are static like module variables (section 2.21): updated in one routine, the value is seen by later calls of another.
! @output 10
! @output 20
! @exit 0
  PERS num total := 0;
  PROC add_ten()
    total := total + 10;
  ENDPROC
  PROC show()
    TPWrite "" \Num:=total;
  ENDPROC
  PROC main()
    add_ten;
    show;
    add_ten;
    show;
  ENDPROC
ENDMODULE
