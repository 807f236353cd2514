MODULE eventlog
  ! The event log while stepping (§7.5, ch. 8): ErrWrite's entries, one of which an IError order
  ! sees, ErrLog's, and SkipWarn in an error handler.
  VAR intnum warned;
  VAR num zero := 0;
  VAR num x;
  TRAP on_warning
    TPWrite "trap: a warning was logged";
  ENDTRAP
  PROC main()
    CONNECT warned WITH on_warning;
    IError USER_DEF_ERR, TYPE_WARN, warned;
    ErrWrite "Header", "an error entry";
    ErrWrite \W, "Header", "a warning entry" \RL2:="line two";
    ErrLog 4800, "one", "two", "", "", "";
    x := 1 / zero;
    TPWrite "end";
  ERROR
    SkipWarn;
    TRYNEXT;
  ENDPROC
ENDMODULE
