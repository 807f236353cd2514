MODULE record_with_semi_value_component
! @format 2
! @section 2.16
! @expect ok
! @description A record with a semi-value component and value components otherwise is a semi-value type: a variable without initialisation is legal.
  RECORD sensor
    signaldi sig;
    num limit;
  ENDRECORD
  VAR sensor s;
  VAR sensor pair_of{2};
ENDMODULE
