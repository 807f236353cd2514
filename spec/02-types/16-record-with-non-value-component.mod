MODULE record_with_non_value_component
! @format 2
! @section 2.16
! @expect semantic-error 10:8
! @description A record with a non-value component is a non-value type, so it cannot be persistent; refused at the data type name.
  RECORD port
    iodev dev;
    num id;
  ENDRECORD
  PERS port main_port;
ENDMODULE
