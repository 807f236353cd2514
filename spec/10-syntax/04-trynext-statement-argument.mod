MODULE trynext_statement_argument
! @section 4.14
! @expect syntax-error 6:13
! @description <trynext statement> ::= TRYNEXT ';'.
  PROC main()
    TRYNEXT 1;
  ENDPROC
ENDMODULE
