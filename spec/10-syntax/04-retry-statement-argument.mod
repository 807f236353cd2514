MODULE retry_statement_argument
! @section 4.13
! @expect syntax-error 6:11
! @description <retry statement> ::= RETRY ';'.
  PROC main()
    RETRY 3;
  ENDPROC
ENDMODULE
