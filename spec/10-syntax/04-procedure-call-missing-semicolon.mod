MODULE procedure_call_missing_semicolon
! @section 4.6
! @expect syntax-error 7:5
! @description A procedure call ends with ';'.
  PROC main()
    p 1
    ENDPROC
  ENDPROC
ENDMODULE
