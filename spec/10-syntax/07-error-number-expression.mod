MODULE error_number_expression
! @section 7.2
! @expect syntax-error 6:13
! @description An error number of a recovery point is not an expression.
  PROC p()
  ERROR (50 + 6)
  ENDPROC
ENDMODULE
