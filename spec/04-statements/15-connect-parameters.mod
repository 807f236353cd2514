MODULE connect_parameters
! @format 2
! @section 4.15
! @expect ok
! @description A VAR or INOUT parameter may be the target of a connect statement.
  PROC attach(VAR intnum ino, INOUT intnum other)
    CONNECT ino WITH on_event;
    CONNECT other WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
