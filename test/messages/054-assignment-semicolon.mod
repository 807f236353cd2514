MODULE t
! @expect-message 5:5: syntax error: expected ';' to end the assignment (§4.5, §4.2); found the identifier y
  PROC main()
    x := 1
    y := 2;
  ENDPROC
ENDMODULE
