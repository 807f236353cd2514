MODULE strmap_use
! @format 3
! @section 13
! @expect ok
! @description StrMap replaces each character found in FromMap by the character at the same place in ToMap (installed-facts.md section 1's examples).
! @output RObOtIcs
! @output ABB IRB
! @exit 0
  PROC main()
    TPWrite StrMap("Robotics", "aeiou", "AEIOU");
    TPWrite StrMap("abb irb", STR_LOWER, STR_UPPER);
  ENDPROC
ENDMODULE
