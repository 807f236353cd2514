MODULE exit_statement_argument
! @section 4.12
! @expect syntax-error 6:10
! @description <exit statement> ::= EXIT ';'.
  PROC main()
    EXIT 0;
  ENDPROC
ENDMODULE
