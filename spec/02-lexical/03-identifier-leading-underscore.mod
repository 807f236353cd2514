MODULE identifier_leading_underscore
! @section 2.3
! @expect lexical-error 5:11
! @description An identifier begins with a letter: "_" cannot begin a token.
  VAR num _x;
ENDMODULE
