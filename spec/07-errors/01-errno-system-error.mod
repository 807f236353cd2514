MODULE errno_system_error
! @format 3
! @section 7.1
! @section 12
! @expect ok
! @description An execution error passes control to the routine's error handler, where the predefined variable ERRNO holds the error's number (section 7.1): here ERR_DIVZERO.
! @output before
! @output divzero=TRUE
! @output outofbnd=FALSE
! @exit 0
  PROC main()
    VAR num d;
    VAR num x;
    TPWrite "before";
    x := 1 / d;
    TPWrite "wrong";
  ERROR
    TPWrite "divzero=" \Bool:=ERRNO = ERR_DIVZERO;
    TPWrite "outofbnd=" \Bool:=ERRNO = ERR_OUTOFBND;
    RETURN;
  ENDPROC
ENDMODULE
