MODULE identifier_leading_digit
! @section 2.3
! @section 2.2
! @expect lexical-error 6:11
! @description An identifier begins with a letter: 2nd is the literal 2 touching the identifier nd.
  VAR num 2nd;
ENDMODULE
