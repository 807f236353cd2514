MODULE declaration_in_parameter_semi
! @format 2
! @section 2.16
! @expect semantic-error 6:13
! @description Table of section 2.16, row routine parameter in, column semi-value: illegal; refused at the data type name.
  PROC show(signaldi di1)
  ENDPROC
ENDMODULE
