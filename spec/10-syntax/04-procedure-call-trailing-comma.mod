MODULE procedure_call_trailing_comma
! @section 4.6
! @expect syntax-error 6:10
! @description ',' in a procedure argument list is followed by an argument.
  PROC main()
    p 1, ;
  ENDPROC
ENDMODULE
