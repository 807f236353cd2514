MODULE procedure_call_missing_comma
! @section 4.6
! @expect syntax-error 6:9
! @description Required procedure arguments are separated by commas.
  PROC main()
    p 1 2;
  ENDPROC
ENDMODULE
