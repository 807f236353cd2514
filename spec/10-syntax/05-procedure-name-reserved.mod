MODULE procedure_name_reserved
! @section 5.4
! @expect syntax-error 5:8
! @description <procedure name> ::= <identifier>: a reserved word is not one.
  PROC IF()
  ENDPROC
ENDMODULE
