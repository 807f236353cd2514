MODULE declaration_in_parameter_non
! @format 2
! @section 2.16
! @expect semantic-error 6:13
! @description Table of section 2.16, row routine parameter in, column non-value: illegal; refused at the data type name.
  PROC show(iodev dev)
  ENDPROC
ENDMODULE
