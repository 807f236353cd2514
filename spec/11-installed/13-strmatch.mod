MODULE strmatch_use
! @format 3
! @section 13
! @expect ok
! @description StrMatch gives the position where Pattern begins, searching from ChPos (installed-facts.md section 1: StrMatch("Robotics",1,"bo") = 3).
! @output 3
! @output 4
! @exit 0
  PROC main()
    TPWrite "" \Num:=StrMatch("Robotics", 1, "bo");
    TPWrite "" \Num:=StrMatch("abcabc", 2, "abc");
  ENDPROC
ENDMODULE
