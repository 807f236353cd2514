MODULE undo_after_reraise
! @format 3
! @section 1.2
! @section 4.11
! @expect ok
! @description A routine whose error handler passes the error on with RAISE; is abandoned when the error leaves it: its own handler runs first, then its UNDO handler, then the caller's handler.
! @output p handler
! @output p undo
! @output main handler
! @exit 0
  PROC p()
    RAISE 3;
  ERROR
    TPWrite "p handler";
    RAISE;
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
