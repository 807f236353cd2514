MODULE declaration_persistent_non_value
! @format 2
! @section 2.16
! @expect semantic-error 6:8
! @description Table of section 2.16, row persistent, column non-value: illegal; refused at the data type name.
  PERS iodev dev;
ENDMODULE
