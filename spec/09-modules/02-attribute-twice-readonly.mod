MODULE attribute_twice_readonly(READONLY, READONLY)
! @format 2
! @section 9.2
! @expect semantic-error 1:43
! @description READONLY twice; the repetition is refused.
  VAR num n;
ENDMODULE
