MODULE identifier_33_characters
! @section 2.3
! @expect lexical-error 5:11
! @description An identifier of 33 characters exceeds the limit of 32.
  VAR num abcdefghijklmnopqrstuvwxyz_123456;
ENDMODULE
