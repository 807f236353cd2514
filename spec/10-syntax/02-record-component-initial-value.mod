MODULE record_component_initial_value
! @section 2.14
! @expect syntax-error 6:11
! @description A record component has no initial value.
  RECORD r
    num a := 1;
  ENDRECORD
ENDMODULE
