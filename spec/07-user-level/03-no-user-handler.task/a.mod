MODULE user_no_handler
! @format 3
! @section 7.3
! @expect ok
! @description RaiseToUser when the routine at the user level has no error handler: the system error handler stops the task (ABB's RaiseToUser; doc/rulings.md R-7.3-n), and reports the error at the user level: at the call in user code that led into the NOSTEPIN routines (doc/rulings.md R-7.3-o).
! @output start
! @exit 1
! @error 7 a.mod:19:5
  PROC main()
    TPWrite "start";
    work;
  ERROR
    TPWrite "main handler";
    TRYNEXT;
  ENDPROC
  PROC work()
    VAR num n;
    n := 1;
    tool;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
