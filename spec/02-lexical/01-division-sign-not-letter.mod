MODULE division_sign_not_letter
! @section 2.1
! @expect lexical-error 5:11
! @description U+00F7 (division sign) lies among the Latin-1 lower case letters but is not a letter.
  VAR num ÷x;
ENDMODULE
