MODULE raise_without_number_in_backward
! @format 2
! @section 4.11
! @section 6.2
! @expect semantic-error 10:5
! @description A backward handler is not an error handler; RAISE without a number there is refused at RAISE.
  PROC main()
    DebugBreak;
  BACKWARD
    RAISE;
  ENDPROC
ENDMODULE
