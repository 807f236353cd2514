MODULE undo_propagated_error
! @format 3
! @section 1.2
! @section 7.2
! @expect ok
! @description A routine left by a propagated error (it has no error handler) is abandoned: its UNDO handler runs, before the handler of the caller that takes the error (section 1.2: the UNDO handler runs when the routine is aborted).
! @output in p
! @output p undo
! @output main handler
! @exit 0
  PROC p()
    TPWrite "in p";
    RAISE 3;
  UNDO
    TPWrite "p undo";
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "main handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
