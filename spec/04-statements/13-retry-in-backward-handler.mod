MODULE retry_in_backward_handler
! @format 2
! @section 4.13
! @section 6.2
! @expect semantic-error 10:5
! @description RETRY in a backward handler is refused at RETRY.
  PROC main()
    DebugBreak;
  BACKWARD
    RETRY;
  ENDPROC
ENDMODULE
