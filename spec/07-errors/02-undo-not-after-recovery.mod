MODULE undo_not_after_recovery
! @format 3
! @section 1.2
! @section 7.1
! @expect ok
! @description A routine whose own error handler recovers (TRYNEXT, or RETURN to the caller) is not abandoned: its UNDO handler does not run.
! @output p handler
! @output p end
! @output q handler
! @output main end
! @exit 0
  PROC p()
    RAISE 1;
    TPWrite "p end";
  ERROR
    TPWrite "p handler";
    TRYNEXT;
  UNDO
    TPWrite "wrong: p undo";
  ENDPROC
  PROC q()
    RAISE 2;
  ERROR
    TPWrite "q handler";
    RETURN;
  UNDO
    TPWrite "wrong: q undo";
  ENDPROC
  PROC main()
    p;
    q;
    TPWrite "main end";
  ENDPROC
ENDMODULE
