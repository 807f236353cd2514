MODULE error_in_backward
! @format 3
! @section 6.1
! @expect ok
! @description An error in a BACKWARD handler cannot be handled by an error handler (section 6.1): run forward, the same error in the body is handled by the routine's handler; run backward (test/golden/debug-back-error.cmd) it goes to the system error handler although both the routine and its caller have error handlers.
! @exit 0
! @output handled 1
! @output after
  VAR num zero := 0;
  VAR num x := 0;
  PROC Divide()
    x := 1 / zero;
  BACKWARD
    x := 1 / zero;
  ERROR
    TPWrite "handled " \Num:=1;
    TRYNEXT;
  ENDPROC
  PROC main()
    Divide;
    TPWrite "after";
  ERROR
    TPWrite "main handled";
    TRYNEXT;
  ENDPROC
ENDMODULE
