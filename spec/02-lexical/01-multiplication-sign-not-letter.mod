MODULE multiplication_sign_not_letter
! @section 2.1
! @expect lexical-error 5:12
! @description U+00D7 (multiplication sign) lies among the Latin-1 upper case letters but is not a letter.
  VAR num a×b;
ENDMODULE
