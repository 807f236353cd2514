MODULE t
! @expect-message 6:5: syntax error: expected ';' to end the GOTO statement (§4.7, §4.2); found the identifier next
! @expect-hint ';' is missing at the end of line 5: a simple statement and a declaration end with ';' (§4.3, §2.18)
  PROC main()
    GOTO next
    next:
  ENDPROC
ENDMODULE
