MODULE raise_new_error_from_handler
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description Dialect, R-4.11-handler1: RAISE with an error number in an error handler ends the handler and raises the new error at the call of the routine, as RAISE without number does for the current one; it propagates through a routine without handler, and the caller's handler sees the new number in ERRNO.
! @output inner handler ERR_DIVZERO=TRUE
! @output main handler 42
! @output after outer
! @exit 0
  CONST errnum ERR_MINE := 42;
  PROC inner()
    VAR num zero;
    VAR num x;
    x := 1 / zero;
    TPWrite "not after the error";
  ERROR
    TPWrite "inner handler ERR_DIVZERO=" \Bool:=ERRNO = ERR_DIVZERO;
    IF ERRNO = ERR_DIVZERO RAISE ERR_MINE;
    TPWrite "not after RAISE";
  ENDPROC
  PROC outer()
    inner;
    TPWrite "not in outer";
  ENDPROC
  PROC main()
    outer;
    TPWrite "after outer";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
