MODULE retry_outside_error_handler
! @format 2
! @section 4.13
! @expect semantic-error 7:5
! @description RETRY restarts the statement that caused an error and belongs in an error handler; in the body it is refused at RETRY.
  PROC main()
    RETRY;
  ENDPROC
ENDMODULE
