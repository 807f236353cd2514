MODULE t
! @expect-message 6:7: syntax error: expected ',' or ':' after the test value (§4.20); found the identifier x
  PROC main()
    TEST mode
    CASE 1
      x := 1;
    ENDTEST
  ENDPROC
ENDMODULE
