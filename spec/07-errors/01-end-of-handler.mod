MODULE end_of_handler
! @format 3
! @section 7.1
! @expect ok
! @description Reaching the end of an error handler (ENDPROC) without RETRY, TRYNEXT, RETURN or RAISE calls the system error handler (section 7.1), which reports the error where it occurred and stops the task.
! @output handler
! @exit 1
! @error ERR_DIVZERO 12:5
  PROC main()
    VAR num d;
    VAR num x;
    x := 1 / d;
    TPWrite "wrong";
  ERROR
    TPWrite "handler";
  ENDPROC
ENDMODULE
