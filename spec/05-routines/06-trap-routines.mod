MODULE trap_routines
! @format 2
! @section 5.6
! @expect ok
! @description Section 5.6's traps low_pressure and high_pressure, which call procedures with a switch.
  PROC open_valve(\switch slow)
  ENDPROC
  PROC close_valve(\switch fast)
  ENDPROC
  TRAP low_pressure
    open_valve\slow;
    ! return to point of interrupt
    RETURN;
  ENDTRAP
  TRAP high_pressure
    close_valve\fast;
    ! return to point of interrupt
    RETURN;
  ENDTRAP
ENDMODULE
