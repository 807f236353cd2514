MODULE egm_setup_no_device
! @format 3
! @section 13
! @expect ok
! @description EGMSetupUC (ABB's EGMSetupUC; doc/rulings.md R-13-egm1): a UCDevice the run does not configure (no --egm-device) is ERR_UDPUC_COMM, and the process stays disconnected; an egmident EGMGetId did not give, or a \CommTimeout that is not a positive time, is ERR_ARGVALERR.
! @output no device ERR_UDPUC_COMM
! @output state 0
! @output no process ERR_ARGVALERR
! @output bad timeout ERR_ARGVALERR
! @exit 0
  VAR egmident id;
  VAR egmident other;
  VAR num stage := 0;
  PROC main()
    EGMGetId id;
    EGMSetupUC ROB_1, id, "default", "UCdevice" \Joint \CommTimeout:=1;
    TPWrite "state " \Num:=EGMGetState(id);
    stage := 1;
    EGMSetupUC ROB_1, other, "default", "UCdevice" \Joint;
    stage := 2;
    EGMSetupUC ROB_1, id, "default", "UCdevice" \Joint \CommTimeout:=0;
  ERROR
    IF stage = 0 AND ERRNO = ERR_UDPUC_COMM THEN
      TPWrite "no device ERR_UDPUC_COMM";
      TRYNEXT;
    ELSEIF stage = 1 AND ERRNO = ERR_ARGVALERR THEN
      TPWrite "no process ERR_ARGVALERR";
      TRYNEXT;
    ELSEIF stage = 2 AND ERRNO = ERR_ARGVALERR THEN
      TPWrite "bad timeout ERR_ARGVALERR";
      RETURN;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
