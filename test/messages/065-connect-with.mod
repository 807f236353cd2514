MODULE t
! @expect-message 4:17: syntax error: expected WITH and the trap routine after the connect target (§4.15); found the identifier StopTrap
  PROC main()
    CONNECT irq StopTrap;
  ENDPROC
ENDMODULE
