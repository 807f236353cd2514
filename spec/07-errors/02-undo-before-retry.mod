MODULE undo_before_retry
! @format 3
! @section 1.2
! @section 4.13
! @expect ok
! @description The abandoned call's UNDO handler runs once, when the error leaves it; the caller's RETRY then makes a new call, which ends normally and runs no UNDO.
! @output p start 1
! @output p undo 1
! @output main handler
! @output p start 2
! @output p end 2
! @exit 0
  VAR num calls;
  PROC p()
    calls := calls + 1;
    TPWrite "p start " \Num:=calls;
    IF calls = 1 RAISE 9;
    TPWrite "p end " \Num:=calls;
  UNDO
    TPWrite "p undo " \Num:=calls;
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "main handler";
    RETRY;
  ENDPROC
ENDMODULE
