MODULE egm_order
! @format 3
! @section 13
! @expect ok
! @egm-device EGMSensor=127.0.0.1:9
! @description The order of an EGM process (ABB's EGM application manual: EGMGetId, EGMSetupUC, EGMActJoint, EGMRunJoint; doc/rulings.md R-13-egm2, R-13-egm3): EGMActJoint before EGMSetupUC, and EGMRunJoint before EGMActJoint, are ERR_ARGVALERR; EGMSetupUC on a configured device connects the process (EGM_STATE_CONNECTED, the device named letter case aside, a trailing ':' ignored); EGMActJoint's \SampleRate is a multiple of the 4 ms cycle, its egm_minmax a range with min <= max; EGMStop of a process that does not run does nothing.
! @output act before setup ERR_ARGVALERR
! @output connected 1
! @output run before act ERR_ARGVALERR
! @output sample rate 6 ERR_ARGVALERR
! @output min above max ERR_ARGVALERR
! @output activated 1
! @output stopped 1
  VAR egmident id;
  VAR num stage := 0;
  PROC main()
    EGMGetId id;
    EGMActJoint id;
    stage := 1;
    EGMSetupUC ROB_1, id, "default", "egmsensor:" \Joint;
    TPWrite "connected " \Num:=EGMGetState(id);
    EGMRunJoint id, EGM_STOP_HOLD \J1;
    stage := 2;
    EGMActJoint id \SampleRate:=6;
    stage := 3;
    EGMActJoint id \J1:=[1, -1];
    stage := 4;
    EGMActJoint id \J1:=[-1, 1] \LpFilter:=20 \SampleRate:=8 \MaxPosDeviation:=100 \MaxSpeedDeviation:=50;
    TPWrite "activated " \Num:=EGMGetState(id);
    EGMStop id, EGM_STOP_RAMP_DOWN \RampOutTime:=0.5;
    TPWrite "stopped " \Num:=EGMGetState(id);
  ERROR
    IF ERRNO = ERR_ARGVALERR THEN
      TEST stage
      CASE 0: TPWrite "act before setup ERR_ARGVALERR";
      CASE 1: TPWrite "run before act ERR_ARGVALERR";
      CASE 2: TPWrite "sample rate 6 ERR_ARGVALERR";
      CASE 3: TPWrite "min above max ERR_ARGVALERR";
      ENDTEST
      TRYNEXT;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
