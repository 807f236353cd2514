MODULE t
! @expect-message 6:5: syntax error: expected a statement, or a keyword that closes the statement list such as ENDIF or ENDPROC (§4.3); data declarations go before the first statement (§5.4); found VAR
  PROC main()
    x := 1;
    y := 2;
    VAR num z;
  ENDPROC
ENDMODULE
