MODULE undo_not_on_system_stop
! @format 3
! @section 1.2
! @section 7.1
! @expect ok
! @description The system error handler stops the task where it is, without abandoning the routines still active (doc/rulings.md R-7.1-b): the entry routine's UNDO handler does not run; a routine the error left before (p, no handler) was abandoned then and ran its UNDO.
! @output p undo
! @exit 1
! @error ERR_DIVZERO 13:5
  PROC p()
    VAR num d;
    VAR num x;
    x := 1 / d;
  UNDO
    TPWrite "p undo";
  ENDPROC
  PROC main()
    p;
  UNDO
    TPWrite "wrong: main undo";
  ENDPROC
ENDMODULE
