MODULE goto_statement_number
! @section 4.7
! @expect syntax-error 6:10
! @description GOTO names a label, which is an identifier.
  PROC main()
    GOTO 10;
  ENDPROC
ENDMODULE
