MODULE no_handler_stops_task
! @format 3
! @section 7.1
! @expect ok
! @description No routine of the call chain has an error handler: at the top (the entry routine) the system error handler reports the error, at the statement where it occurred, and stops the task (section 7.1): exit 1.
! @output start
! @exit 1
! @error ERR_DIVZERO 12:5
  PROC inner()
    VAR num d;
    VAR num x;
    x := 1 / d;
  ENDPROC
  PROC outer()
    inner;
  ENDPROC
  PROC main()
    TPWrite "start";
    outer;
    TPWrite "wrong";
  ENDPROC
ENDMODULE
