MODULE procedure_call_leading_comma
! @section 4.6
! @expect syntax-error 6:7
! @description A procedure argument list does not begin with a comma.
  PROC main()
    p , 1;
  ENDPROC
ENDMODULE
