MODULE raise_new_error_long_jump
! @format 3
! @section 4.11
! @section 7.2
! @expect ok
! @description Dialect, R-4.11-handler1: the new error a handler raises is searched for from the caller up, as any error that leaves a routine (section 7.2): the recovery point ERROR (56) of main takes it, the handler of middle is skipped, and the UNDO handlers of the abandoned routines run, innermost first.
! @output undo inner
! @output undo middle
! @output recovery point 56
! @output done
! @exit 0
  VAR bool again := TRUE;
  PROC inner()
    VAR num zero;
    VAR num x;
    x := 1 / zero;
  ERROR
    RAISE 56;
  UNDO
    TPWrite "undo inner";
  ENDPROC
  PROC middle()
    inner;
  ERROR
    TPWrite "not the handler of middle";
    RETURN;
  UNDO
    TPWrite "undo middle";
  ENDPROC
  PROC main()
    IF again middle;
    TPWrite "done";
  ERROR (56)
    TPWrite "recovery point " \Num:=ERRNO;
    again := FALSE;
    RETRY;
  ENDPROC
ENDMODULE
