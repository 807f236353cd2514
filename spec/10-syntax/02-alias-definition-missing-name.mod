MODULE alias_definition_missing_name
! @section 2.15
! @expect syntax-error 5:12
! @description <alias definition> ::= ALIAS <data type> <identifier> ';': the new name may not be left out.
  ALIAS num;
ENDMODULE
