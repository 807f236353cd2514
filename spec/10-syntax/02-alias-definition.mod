MODULE alias_definition
! @section 2.15
! @expect ok
! @description The alias examples of sections 2.11 and 2.15 (level, used there, is declared as an alias of num).
  ALIAS num newtype;
  ALIAS num level;
  ALIAS num another_num;
  CONST level low := 2.5;
  CONST level high := 4.0;
ENDMODULE
