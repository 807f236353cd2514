MODULE strmemb_use
! @format 3
! @section 13
! @expect ok
! @description StrMemb tells whether the character at ChPos is in Set (installed-facts.md section 1: position 2 of "Robotics" is a vowel, position 3 is not).
! @output TRUE
! @output FALSE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=StrMemb("Robotics", 2, "aeiou");
    TPWrite "" \Bool:=StrMemb("Robotics", 3, "aeiou");
  ENDPROC
ENDMODULE
