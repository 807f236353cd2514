MODULE t
! @expect-message 4:16: syntax error: expected an operator or ')' (§3.1); found ';'
  PROC main()
    x := (y + 1;
  ENDPROC
ENDMODULE
