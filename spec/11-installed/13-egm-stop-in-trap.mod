MODULE egm_stop_in_trap
! @format 3
! @section 13
! @section 8
! @expect ok
! @egm-device EGMSensor=127.0.0.1:9
! @statement-time 0
! @description EGMRunJoint is a waiting instruction during which interrupts are served (doc/rulings.md R-13-egm2, R-13-egm4): a timer's trap at 0.102 s finds the process running and calls EGMStop, and the run ends at its next cycle (0.104 s: cycles every 4 ms from the call) without an error, the process connected again. A second run, left by the long jump of a trap's RAISE to an ERROR (33) handler (§7.2), leaves the process connected too.
! @output trap at 0.102 s: EGMStop
! @output running in the trap TRUE
! @output stopped at 0.104 s
! @output state 1
! @output trap at 0.050 s: RAISE 33
! @output left by the long jump 1
  VAR egmident id;
  VAR clock c;
  VAR intnum tick;
  VAR intnum jump;
  PROC main()
    EGMGetId id;
    EGMSetupUC ROB_1, id, "default", "EGMSensor" \Joint \CommTimeout:=1;
    EGMActJoint id \MaxSpeedDeviation:=100;
    CONNECT tick WITH on_tick;
    ITimer \Single, 0.102, tick;
    ClkStart c;
    EGMRunJoint id, EGM_STOP_HOLD \J1 \CondTime:=1;
    TPWrite "stopped at " + NumToStr(ClkRead(c), 3) + " s";
    TPWrite "state " \Num:=EGMGetState(id);
    second_run;
  ENDPROC
  PROC second_run()
    CONNECT jump WITH raising;
    ITimer \Single, 0.05, jump;
    ClkReset c;
    ClkStart c;
    EGMRunJoint id, EGM_STOP_HOLD \J1 \CondTime:=1;
    TPWrite "not here";
  ERROR (33)
    TPWrite "left by the long jump " \Num:=EGMGetState(id);
    RETURN;
  ENDPROC
  TRAP raising
    TPWrite "trap at " + NumToStr(ClkRead(c), 3) + " s: RAISE 33";
    RAISE 33;
  ENDTRAP
  TRAP on_tick
    TPWrite "trap at " + NumToStr(ClkRead(c), 3) + " s: EGMStop";
    TPWrite "running in the trap " \Bool:=EGMGetState(id) = EGM_STATE_RUNNING;
    EGMStop id, EGM_STOP_HOLD;
  ENDTRAP
ENDMODULE
