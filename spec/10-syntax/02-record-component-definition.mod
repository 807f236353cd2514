MODULE record_component_definition
! @section 2.14
! @expect ok
! @description <record component definition> ::= <data type> <record component name> ';', any number per line.
  RECORD r
    num a;
    string b; bool c;
    pos <ID>;
    <ID> d;
  ENDRECORD
ENDMODULE
