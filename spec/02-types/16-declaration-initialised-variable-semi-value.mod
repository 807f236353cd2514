MODULE declaration_initialised_variable
! @format 2
! @section 2.16
! @expect semantic-error 6:7
! @description Table of section 2.16, row variable with initialisation, column semi-value: not applicable; refused at the data type name.
  VAR signaldi di1 := <EXP>;
ENDMODULE
