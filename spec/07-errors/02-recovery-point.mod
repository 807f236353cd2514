MODULE recovery_point
! @format 3
! @section 7.2
! @expect ok
! @description Section 7.2's first example: main's ERROR (56, ERR_DIVZERO) is an error recovery point; a division by zero in myRoutine, which has no handler, reaches it and RETRY calls myRoutine again (which then finds a divisor).
! @output myRoutine 1
! @output recovery point divzero=TRUE
! @output myRoutine 2
! @output done
! @exit 0
  VAR num calls;
  VAR num divisor;
  PROC myRoutine()
    VAR num x;
    calls := calls + 1;
    TPWrite "myRoutine " \Num:=calls;
    x := 1 / divisor;
  ENDPROC
  PROC main()
    ! Do something important
    myRoutine;
    TPWrite "done";
  ERROR (56, ERR_DIVZERO)
    TPWrite "recovery point divzero=" \Bool:=ERRNO = ERR_DIVZERO;
    divisor := 1;
    RETRY;
  ENDPROC
ENDMODULE
