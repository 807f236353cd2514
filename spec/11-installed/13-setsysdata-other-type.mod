MODULE setsysdata_other_type
! @format 3
! @section 13
! @expect ok
! @description SetSysData given a persistent that is neither a tooldata, a wobjdata nor a loaddata is the execution error ERR_ARGVALERR at the call (doc/rulings.md R-13-y); the error handler sees it.
! @output caught
  PERS num counter := 0;
  PROC main()
    SetSysData counter;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite "caught";
    RETURN;
  ENDPROC
ENDMODULE
