MODULE error_number_placeholder_id
! @section 7.2
! @expect syntax-error 6:10
! @description An entire constant, variable or persistent is an <ident>: <ID> cannot stand for it.
  PROC p()
  ERROR (<ID>)
  ENDPROC
ENDMODULE
