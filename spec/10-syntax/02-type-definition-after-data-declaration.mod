MODULE type_definition_after_data_decla
! @section 2.11
! @section 9.2
! @expect syntax-error 7:3
! @description The type definition list precedes the data declaration list in a module.
  VAR num x;
  RECORD r
    num a;
  ENDRECORD
ENDMODULE
