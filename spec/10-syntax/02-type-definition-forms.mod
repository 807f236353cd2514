MODULE type_definition_forms
! @section 2.11
! @section 2.14
! @section 2.15
! @expect ok
! @description <type definition> ::= [LOCAL] (<record definition> | <alias definition>) | <comment> | <TDN>.
  RECORD r1
    num a;
  ENDRECORD
  LOCAL RECORD r2
    num a;
  ENDRECORD
  ALIAS num a1;
  LOCAL ALIAS num a2;
  ! a comment
  <TDN>
ENDMODULE
