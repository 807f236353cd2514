MODULE strlen_use
! @format 3
! @section 13
! @expect ok
! @description StrLen gives the number of characters (installed-facts.md section 1: StrLen("Robotics") = 8).
! @output 8
! @output 0
! @exit 0
  PROC main()
    TPWrite "" \Num:=StrLen("Robotics");
    TPWrite "" \Num:=StrLen("");
  ENDPROC
ENDMODULE
