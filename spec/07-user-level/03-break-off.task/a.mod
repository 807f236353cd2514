MODULE user_break_off
! @format 3
! @section 7.3
! @section 9.4
! @expect ok
! @description RaiseToUser \BreakOff in the error handler of a routine of a NOSTEPIN module: the NOSTEPIN routines up to the user level are abandoned without their error handlers (outer's is skipped); the UNDO handler of outer runs, not that of inner, whose handler raised the error (doc/rulings.md R-7.3-q); the error is handled by main, the first routine above them, as raised at its call (TRYNEXT goes on after the call).
! @output before
! @output inner handler
! @output outer undo
! @output main handler 7
! @output after
! @exit 0
  PROC main()
    TPWrite "before";
    outer;
    TPWrite "after";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
