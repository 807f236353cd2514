MODULE connect_twice_same_target
! @format 2
! @section 4.15
! @section 12
! @expect ok
! @description Connecting the same target twice is detected when it runs (ERR_ALRDYCNT), not statically.
  VAR intnum ino;
  PROC main()
    CONNECT ino WITH on_event;
    CONNECT ino WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
