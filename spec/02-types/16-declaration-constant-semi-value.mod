MODULE declaration_constant_semi_value
! @format 2
! @section 2.16
! @expect semantic-error 6:9
! @description Table of section 2.16, row constant, column semi-value: not applicable, so no constant of a semi-value type; refused at the data type name.
  CONST signaldi di1 := <EXP>;
ENDMODULE
