MODULE error_number_component
! @section 7.2
! @expect syntax-error 6:11
! @description An error number of a recovery point is an entire data object, not a component.
  PROC p()
  ERROR (a.b)
  ENDPROC
ENDMODULE
