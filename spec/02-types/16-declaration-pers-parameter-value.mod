MODULE declaration_pers_parameter_value
! @format 2
! @section 2.16
! @expect ok
! @description Table of section 2.16, row routine parameter pers, column value: legal.
  PROC keep(PERS num n, PERS pos p)
  ENDPROC
ENDMODULE
