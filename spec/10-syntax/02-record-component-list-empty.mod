MODULE record_component_list_empty
! @section 2.14
! @expect syntax-error 6:3
! @description <record component list> holds at least one <record component definition>.
  RECORD r
  ENDRECORD
ENDMODULE
