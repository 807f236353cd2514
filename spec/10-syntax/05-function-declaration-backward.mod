MODULE function_declaration_backward
! @section 5.5
! @section 6.2
! @expect syntax-error 8:3
! @description Only procedures have a BACKWARD part.
  FUNC num f()
    RETURN 1;
  BACKWARD
  ENDFUNC
ENDMODULE
