MODULE t
! @expect-message 6:7: syntax error: expected ':' after DEFAULT (§4.20); found the identifier x
  PROC main()
    TEST mode
    DEFAULT
      x := 1;
    ENDTEST
  ENDPROC
ENDMODULE
