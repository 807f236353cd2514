MODULE function_name_missing
! @section 5.5
! @expect syntax-error 5:11
! @description FUNC <data type> <function name>: the name may not be left out.
  FUNC num()
    RETURN 1;
  ENDFUNC
ENDMODULE
