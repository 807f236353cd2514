MODULE record_component_array
! @section 2.14
! @expect syntax-error 6:10
! @description A record component has no array dimensions.
  RECORD r
    num a{3};
  ENDRECORD
ENDMODULE
