MODULE error_in_handler
! @format 3
! @section 7.1
! @expect ok
! @description An error inside an error handler cannot be recovered (section 7.1): it goes to the system error handler, which stops the task; the caller's handler is not called.
! @output p handler
! @exit 1
! @error ERR_DIVZERO 15:5
  PROC p()
    VAR num d;
    VAR num x;
    RAISE 5;
  ERROR
    TPWrite "p handler";
    x := 1 / d;
    TPWrite "wrong";
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "wrong main handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
