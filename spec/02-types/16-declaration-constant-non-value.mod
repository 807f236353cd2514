MODULE declaration_constant_non_value
! @format 2
! @section 2.16
! @expect semantic-error 6:9
! @description Table of section 2.16, row constant, column non-value: illegal; refused at the data type name (the value is a placeholder, so the declaration holds no other error).
  CONST iodev dev := <EXP>;
ENDMODULE
