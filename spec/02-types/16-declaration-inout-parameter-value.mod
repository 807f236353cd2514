MODULE declaration_inout_parameter
! @format 2
! @section 2.16
! @expect ok
! @description Table of section 2.16, rows routine parameter inout var and inout pers, column value: legal.
  PROC adjust(INOUT num n, INOUT pos p)
  ENDPROC
ENDMODULE
