MODULE t
! @expect-message 4:15: syntax error: expected '(' after <ID>: in an expression <ID> can only name a function (§3.6, §3.11); found '+'
  PROC main()
    x := <ID> + 1;
  ENDPROC
ENDMODULE
