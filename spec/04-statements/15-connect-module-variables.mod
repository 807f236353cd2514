MODULE connect_module_variables
! @format 2
! @section 4.15
! @section 8
! @expect ok
! @description Section 4.15's and chapter 8's examples: module intnum variables connected to traps, one trap serving two interrupt numbers, an element of an intnum array.
  VAR intnum hp;
  LOCAL VAR intnum empty;
  LOCAL VAR intnum full;
  VAR intnum inos{2};
  PROC main()
    CONNECT hp WITH high_pressure;
    CONNECT empty WITH ftrap;
    CONNECT full WITH ftrap;
    CONNECT inos{2} WITH ftrap;
  ENDPROC
  TRAP high_pressure
    RETURN;
  ENDTRAP
  TRAP ftrap
    RETURN;
  ENDTRAP
ENDMODULE
