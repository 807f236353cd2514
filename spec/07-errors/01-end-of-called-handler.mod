MODULE end_of_called_handler
! @format 3
! @section 7.1
! @expect ok
! @description The end of any error handler in the call chain calls the system error handler (section 7.1): when p's handler ends, the error is not passed to main's handler.
! @output p handler
! @exit 1
! @error 8 10:5
  PROC p()
    RAISE 8;
  ERROR
    TPWrite "p handler";
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "wrong main handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
