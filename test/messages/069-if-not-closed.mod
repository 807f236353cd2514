MODULE t
! @expect-message 6:3: syntax error: expected a statement, ELSEIF, ELSE or ENDIF (§4.16); found ENDPROC
  PROC main()
    IF ok THEN
      x := 1;
  ENDPROC
ENDMODULE
