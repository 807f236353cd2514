MODULE record_component_name_reserved
! @section 2.14
! @expect syntax-error 6:9
! @description <record component name> ::= <identifier>: a reserved word is not one.
  RECORD r
    num TO;
  ENDRECORD
ENDMODULE
