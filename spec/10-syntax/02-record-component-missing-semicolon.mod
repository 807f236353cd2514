MODULE record_component_missing_semicol
! @section 2.14
! @expect syntax-error 7:3
! @description A record component definition ends with ';'.
  RECORD r
    num a
  ENDRECORD
ENDMODULE
