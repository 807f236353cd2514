MODULE t
! @expect-message 4:12: syntax error: expected an index expression after '{' (§3.6); found '}'
  PROC main()
    x := a{};
  ENDPROC
ENDMODULE
