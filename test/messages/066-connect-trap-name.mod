MODULE t
! @expect-message 4:21: syntax error: expected the trap routine's name after WITH (§4.15); found ';'
  PROC main()
    CONNECT irq WITH;
  ENDPROC
ENDMODULE
