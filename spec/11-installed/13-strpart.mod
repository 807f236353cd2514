MODULE strpart_use
! @format 3
! @section 13
! @expect ok
! @description StrPart(Str, ChPos, Len) gives Len characters from position ChPos, counted from 1 (installed-facts.md section 1: StrPart("Robotics",1,5) = "Robot").
! @output Robot
! @output ics
! @exit 0
  PROC main()
    TPWrite StrPart("Robotics", 1, 5);
    TPWrite StrPart("Robotics", 6, 3);
  ENDPROC
ENDMODULE
