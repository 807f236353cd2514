MODULE raise_number_nested_in_handler
! @format 2
! @section 4.11
! @expect semantic-error 9:28
! @description A RAISE with an error number nested in an IF of an error handler is in the handler; refused at RAISE.
  PROC main()
    DebugBreak;
  ERROR
    IF ERRNO = ERR_DIVZERO RAISE 12;
  ENDPROC
ENDMODULE
