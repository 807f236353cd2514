MODULE connect_statement_missing_with
! @section 4.15
! @expect syntax-error 7:16
! @description CONNECT <connect target> WITH <trap>: WITH may not be left out.
  VAR intnum hp;
  PROC main()
    CONNECT hp high_pressure;
  ENDPROC
ENDMODULE
