MODULE raise_in_trap
! @format 3
! @section 8
! @section 4.11
! @expect ok
! @statement-time 0
! @description RAISE in a trap without an error handler goes to the system error handler (installed-facts.md section 6).
! @exit 1
! @error 12 12:5
  VAR intnum t;
  TRAP bad
    RAISE 12;
  ENDTRAP
  PROC main()
    CONNECT t WITH bad;
    ITimer \Single, 0.1, t;
    WaitTime 1;
  ENDPROC
ENDMODULE
