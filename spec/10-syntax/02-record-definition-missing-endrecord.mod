MODULE record_definition_missing_endrec
! @section 2.14
! @expect syntax-error 7:1
! @description RECORD <identifier> <record component list> ENDRECORD: ENDRECORD may not be left out.
  RECORD r
    num x;
ENDMODULE
