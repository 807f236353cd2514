MODULE declaration_var_parameter
! @format 2
! @section 2.16
! @expect ok
! @description Table of section 2.16, row routine parameter var: legal for value, non-value and semi-value types.
  PROC use(VAR num n, VAR iodev dev, VAR signaldi di1 \VAR iodev spare)
  ENDPROC
ENDMODULE
