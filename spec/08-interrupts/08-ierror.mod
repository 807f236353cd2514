MODULE ierror_case
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description IError orders an interrupt for entries of the event log of a domain (COMMON_ERR: any) and type (TYPE_ALL: any); ErrWrite writes such entries (domain USER_DEF_ERR; \W a warning, without a switch an error: doc/rulings.md R-8-l). In the trap, GetTrapData and ReadErrData give the entry's domain, type and text.
! @output user:A warning
! @output user:B error
! @output errors:B error
  VAR intnum user;
  VAR intnum errors;
  VAR trapdata td;
  VAR errdomain dom;
  VAR num id;
  VAR errtype typ;
  VAR string s1;
  VAR string s2;
  TRAP on_entry
    GetTrapData td;
    ReadErrData td, dom, id, typ \Str1:=s1 \Str2:=s2;
    IF INTNO = user AND dom = USER_DEF_ERR THEN
      TPWrite "user:" + s1 + " " + s2;
    ELSEIF INTNO = errors AND typ = TYPE_ERR THEN
      TPWrite "errors:" + s1 + " " + s2;
    ENDIF
  ENDTRAP
  PROC main()
    CONNECT user WITH on_entry;
    IError USER_DEF_ERR, TYPE_ALL, user;
    CONNECT errors WITH on_entry;
    IError COMMON_ERR, TYPE_ERR, errors;
    ErrWrite \W, "A", "warning";
    ErrWrite "B", "error";
    WaitTime 0.1;
  ENDPROC
ENDMODULE
