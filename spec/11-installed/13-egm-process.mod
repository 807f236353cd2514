MODULE egm_process
! @format 3
! @section 13
! @expect ok
! @description An EGM process (ABB's EGMGetId, EGMGetState, EGMReset; doc/rulings.md R-13-egm2): an egmident holds none at first, and EGMGetState says EGM_STATE_DISCONNECTED; EGMReset of it does nothing; EGMGetId gives it one, still disconnected, and a second EGMGetId keeps it; EGMReset releases it, and an EGMGetId after gives a new process. EGM_STATE_DISCONNECTED < EGM_STATE_CONNECTED < EGM_STATE_RUNNING, as programs compare them.
! @output fresh 0
! @output reset of none 0
! @output registered 0
! @output kept TRUE
! @output released 0
! @output registered again 0
! @output order TRUE
  VAR egmident id;
  PROC main()
    TPWrite "fresh " \Num:=EGMGetState(id);
    EGMReset id;
    TPWrite "reset of none " \Num:=EGMGetState(id);
    EGMGetId id;
    TPWrite "registered " \Num:=EGMGetState(id);
    EGMGetId id;
    TPWrite "kept " \Bool:=EGMGetState(id) = EGM_STATE_DISCONNECTED;
    EGMReset id;
    TPWrite "released " \Num:=EGMGetState(id);
    EGMGetId id;
    TPWrite "registered again " \Num:=EGMGetState(id);
    TPWrite "order " \Bool:=EGM_STATE_DISCONNECTED < EGM_STATE_CONNECTED AND EGM_STATE_CONNECTED < EGM_STATE_RUNNING;
  ENDPROC
ENDMODULE
