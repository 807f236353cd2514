MODULE t
! @expect-message 5:5: syntax error: expected ';' to end the GOTO statement (§4.7, §4.2); found the identifier next
  PROC main()
    GOTO next
    next:
  ENDPROC
ENDMODULE
