MODULE user_continue_retry
! @format 3
! @section 7.3
! @expect ok
! @description RaiseToUser \Continue (ABB's name of the switch, doc/rulings.md R-7.3-m): the error handler of the user level (main) handles the error, ERRNO unchanged; its RETRY goes on in the NOSTEPIN routine that caused the error, executing the statement that failed again (section 7.3: execution is resumed in routine3).
! @output before
! @output inner handler
! @output main handler TRUE
! @output inner x 5
! @output outer goes on
! @output after
! @exit 0
  VAR num divisor := 0;
  PROC main()
    TPWrite "before";
    outer;
    TPWrite "after";
  ERROR
    TPWrite "main handler " \Bool:=ERRNO = ERR_DIVZERO;
    divisor := 2;
    RETRY;
  ENDPROC
ENDMODULE
