MODULE goto_statement_no_label
! @section 4.7
! @expect syntax-error 6:9
! @description GOTO names a label.
  PROC main()
    GOTO;
  ENDPROC
ENDMODULE
