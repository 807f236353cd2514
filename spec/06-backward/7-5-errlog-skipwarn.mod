MODULE errlog_skipwarn
! @format 3
! @section 7.5
! @expect ok
! @description ErrLog writes an entry to the event log, not to the FlexPendant's lines; SkipWarn in an error handler keeps the handled error's warning out of the event log (section 7.5). The event log's entries are pinned by test/golden/run-json-errlog.cmd (run --json: errlog and skipwarn events).
! @exit 0
! @output handled
! @output end
  VAR num zero := 0;
  VAR num x := 0;
  PROC main()
    ErrLog 4800, "Argument one", "two", "", "", "";
    ErrLog 4801 \W, "warning", "", "", "", "";
    ErrLog 4802 \I, "information", "", "", "", "";
    x := 1 / zero;
    TPWrite "end";
  ERROR
    SkipWarn;
    TPWrite "handled";
    TRYNEXT;
  ENDPROC
ENDMODULE
