MODULE error_number_list_empty
! @section 7.2
! @expect syntax-error 6:10
! @description <error number list> ::= '(' <error number> { ',' <error number> } ')' holds at least one number.
  PROC p()
  ERROR ()
  ENDPROC
ENDMODULE
