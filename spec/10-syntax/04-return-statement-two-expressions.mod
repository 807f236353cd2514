MODULE return_statement_two_expressions
! @section 4.10
! @expect syntax-error 6:14
! @description <return statement> ::= RETURN [ <expression> ] ';'.
  FUNC num f()
    RETURN 1 2;
  ENDFUNC
ENDMODULE
