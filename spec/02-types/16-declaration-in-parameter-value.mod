MODULE declaration_in_parameter_value
! @format 2
! @section 2.16
! @expect ok
! @description Table of section 2.16, row routine parameter in, column value: legal.
  PROC show(num n, pos p, string s \bool verbose)
  ENDPROC
ENDMODULE
