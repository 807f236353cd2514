MODULE declaration_persistent_semi
! @format 2
! @section 2.16
! @section 14
! @expect semantic-error 7:8
! @description Table of section 2.16, row persistent, column semi-value: not applicable (persistents can only be of value types, ch. 14); refused at the data type name.
  PERS signaldi di1;
ENDMODULE
