MODULE undo_exit_in_handler
! @format 3
! @section 1.2
! @section 4.12
! @expect ok
! @description EXIT in an error handler also abandons the routines of the call chain: the UNDO handlers of the routine and of its callers run, innermost first.
! @output p handler
! @output p undo
! @output main undo
! @exit 0
  PROC p()
    RAISE 2;
  ERROR
    TPWrite "p handler";
    EXIT;
  UNDO
    TPWrite "p undo";
  ENDPROC
  PROC main()
    p;
  UNDO
    TPWrite "main undo";
  ENDPROC
ENDMODULE
