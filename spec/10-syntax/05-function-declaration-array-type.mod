MODULE function_declaration_array_type
! @section 5.5
! @expect syntax-error 5:11
! @description A function cannot have dimensions: it cannot return an array.
  FUNC num{*} f()
    RETURN 1;
  ENDFUNC
ENDMODULE
