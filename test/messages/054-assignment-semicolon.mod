MODULE t
! @expect-message 6:5: syntax error: expected ';' to end the assignment (§4.5, §4.2); found the identifier y
! @expect-hint ';' is missing at the end of line 5: a simple statement and a declaration end with ';' (§4.3, §2.18)
  PROC main()
    x := 1
    y := 2;
  ENDPROC
ENDMODULE
