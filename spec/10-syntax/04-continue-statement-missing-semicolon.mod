MODULE continue_statement_missing_semic
! @section 4.9
! @expect syntax-error 8:5
! @description <continue statement> ::= CONTINUE ';'.
  PROC main()
    WHILE TRUE DO
      CONTINUE
    ENDWHILE
  ENDPROC
ENDMODULE
