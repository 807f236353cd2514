MODULE function_declaration_no_type
! @section 5.5
! @expect syntax-error 5:9
! @description FUNC <data type> <function name>: the return type may not be left out.
  FUNC f()
    RETURN 1;
  ENDFUNC
ENDMODULE
