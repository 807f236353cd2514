MODULE trap_declaration
! @section 5.6
! @expect ok
! @description The examples of section 5.6, and a trap with data declarations, ERROR and UNDO parts.
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
  TRAP t
    VAR num x;
    x := 1;
  ERROR
    TRYNEXT;
  UNDO
    x := 0;
  ENDTRAP
ENDMODULE
