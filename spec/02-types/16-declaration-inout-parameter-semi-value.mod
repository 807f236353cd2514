MODULE declaration_inout_parameter_semi
! @format 2
! @section 2.16
! @expect semantic-error 6:21
! @description Table of section 2.16, rows routine parameter inout, column semi-value: illegal; refused at the data type name.
  PROC adjust(INOUT signaldi di1)
  ENDPROC
ENDMODULE
