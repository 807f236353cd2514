MODULE parameter_declaration_switch_wit
! @section 5.2
! @expect syntax-error 5:17
! @description 'switch' <identifier>: a switch parameter has a name.
  PROC p(\switch)
  ENDPROC
ENDMODULE
