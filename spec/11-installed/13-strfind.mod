MODULE strfind_use
! @format 3
! @section 13
! @expect ok
! @description StrFind gives the first position from ChPos whose character is in Set, or with \NotInSet is not (installed-facts.md section 1's examples).
! @output 2
! @output 1
! @output 5
! @output 4
! @exit 0
  PROC main()
    TPWrite "" \Num:=StrFind("Robotics", 1, "aeiou");
    TPWrite "" \Num:=StrFind("Robotics", 1, "aeiou" \NotInSet);
    TPWrite "" \Num:=StrFind("IRB 6400", 1, STR_DIGIT);
    TPWrite "" \Num:=StrFind("Robotics", 3, "aeiou");
  ENDPROC
ENDMODULE
