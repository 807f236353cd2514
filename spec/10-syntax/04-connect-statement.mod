MODULE connect_statement
! @section 4.15
! @expect ok
! @description The example of section 4.15, and an element, <VAR> and <ID> in a connect statement.
  VAR intnum hp;
  VAR intnum inos{2};
  PROC main()
    CONNECT hp WITH high_pressure;
    CONNECT inos{1} WITH high_pressure;
    CONNECT <VAR> WITH high_pressure;
    CONNECT hp WITH <ID>;
  ENDPROC

  TRAP high_pressure
    close_valve\fast;
    RETURN;
  ENDTRAP
ENDMODULE
