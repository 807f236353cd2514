MODULE t
! @expect-message 5:7: syntax error: expected ':=' for an assignment, ':' for a label, or the arguments or ';' of a procedure call (§4.4, §4.5, §4.6); found '='
! @expect-hint an assignment is written ':=' (§4.5)
  PROC main()
    x = 5;
  ENDPROC
ENDMODULE
