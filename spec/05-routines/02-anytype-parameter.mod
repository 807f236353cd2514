MODULE anytype_parameter
! @format 2
! @section 5.2
! @section 11
! @expect semantic-error 7:13
! @description anytype marks parameters of installed routines only; a RAPID routine cannot have an anytype parameter; refused at the type name.
  PROC show(anytype x)
  ENDPROC
ENDMODULE
