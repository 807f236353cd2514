MODULE declaration_pers_parameter_non
! @format 2
! @section 2.16
! @expect semantic-error 6:18
! @description Table of section 2.16, row routine parameter pers, column non-value: illegal; refused at the data type name.
  PROC keep(PERS iodev dev)
  ENDPROC
ENDMODULE
