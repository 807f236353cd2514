MODULE connect_placeholders
! @format 2
! @section 4.15
! @section 2.9
! @expect ok
! @description <VAR> stands for a connect target without a semantic error.
  PROC main()
    CONNECT <VAR> WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
