MODULE t
! @expect-message 7:16: syntax error: expected an operator or ')' (§3.1); found ','
! @expect-hint a procedure call takes its arguments without parentheses (§4.6): write greet "Bob", 2; instead of greet("Bob", 2);
  PROC greet(string name, num n)
  ENDPROC
  PROC main()
    greet("Bob", 2);
  ENDPROC
ENDMODULE
