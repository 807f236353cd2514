MODULE declaration_initialised_variable
! @format 2
! @section 2.16
! @expect semantic-error 6:7
! @description Table of section 2.16, row variable with initialisation, column non-value: illegal; refused at the data type name.
  VAR iodev dev := <EXP>;
ENDMODULE
