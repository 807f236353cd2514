MODULE ierror_not_log
! @format 3
! @section 7.5
! @section 8
! @expect ok
! @statement-time 0
! @description The warning a handled error writes to the event log (section 7.5) and an ErrLog entry are not entries IError sees: an IError order for every domain and type is served for the ErrWrite entry only (doc/rulings.md R-7.5-m, R-7.5-n, R-8-l).
! @output handled
! @output entries 1
  VAR intnum all;
  VAR num n := 0;
  VAR num zero := 0;
  VAR num x;
  TRAP on_entry
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT all WITH on_entry;
    IError COMMON_ERR, TYPE_ALL, all;
    x := 1 / zero;
    ErrLog 4800, "one", "two", "", "", "";
    WaitTime 0.1;
    ErrWrite "header", "reason";
    WaitTime 0.1;
    TPWrite "entries " \Num:=n;
  ERROR
    TPWrite "handled";
    TRYNEXT;
  ENDPROC
ENDMODULE
