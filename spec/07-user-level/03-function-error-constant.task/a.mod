MODULE user_function_error_constant
! @format 3
! @section 7.3
! @section 5.5
! @expect ok
! @description RaiseToUser in the error handler of a NOSTEPIN function, with an installed error constant as \ErrorNumber: the statement of main that calls the function (in its expression) is the call at the user level; main's handler sees ERR_ARGVALERR in ERRNO, and its RETRY goes on in the function, which then returns normally (section 7.3, doc/rulings.md R-7.3-p, R-7.3-q).
! @output main handler TRUE
! @output value 6
! @exit 0
  VAR num factor := 0;
  PROC main()
    VAR num v;
    v := Scaled(3) + 1;
    TPWrite "value " \Num:=v - 1;
  ERROR
    TPWrite "main handler " \Bool:=ERRNO = ERR_ARGVALERR;
    factor := 2;
    RETRY;
  ENDPROC
ENDMODULE
