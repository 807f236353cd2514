MODULE alias_of_alias
! @format 2
! @section 2.15
! @expect semantic-error 7:9
! @description An alias type may not be defined on another alias type; refused at the base type name of the second ALIAS.
  ALIAS num level;
  ALIAS level sublevel;
ENDMODULE
