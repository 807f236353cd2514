MODULE break_statement_argument
! @section 4.8
! @expect syntax-error 7:13
! @description <break statement> ::= BREAK ';'.
  PROC main()
    WHILE TRUE DO
      BREAK 1;
    ENDWHILE
  ENDPROC
ENDMODULE
