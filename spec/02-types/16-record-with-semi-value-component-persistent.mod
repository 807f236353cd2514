MODULE record_with_semi_value_component
! @format 2
! @section 2.16
! @expect semantic-error 10:8
! @description A record with a semi-value component is a semi-value type: no persistent of it; refused at the data type name.
  RECORD sensor
    signaldi sig;
    num limit;
  ENDRECORD
  PERS sensor s;
ENDMODULE
