MODULE iounitstate_not_modelled
! @format 3
! @section 11
! @expect ok
! @description IOUnitState (ABB, RobotWare 6) and its iounit_state constants are installed, so a program comparing a device's state checks; rapid-sem reads no I/O device of the configuration, so running it is "not modelled" (exit 4) at the call (doc/rulings.md R-13-motset1).
! @exit 4
! @error IOUnitState 10:8
  PROC main()
    VAR iounit_state s := IOUNIT_PHYS_STATE_RUNNING;
    IF IOUnitState("d652" \Logic) = IOUNIT_LOG_STATE_ENABLED TPWrite "enabled";
  ENDPROC
ENDMODULE
