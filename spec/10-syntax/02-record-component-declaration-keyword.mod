MODULE record_component_declaration_key
! @section 2.14
! @expect syntax-error 6:5
! @description A record component is <data type> <name>, not a variable declaration.
  RECORD r
    VAR num a;
  ENDRECORD
ENDMODULE
