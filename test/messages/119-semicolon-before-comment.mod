MODULE t
! @expect-message 5:12: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found a comment
! @expect-hint ';' is missing before the comment on line 5: a simple statement and a declaration end with ';' (§4.3, §2.18)
  PROC main()
    a := 1 ! one
  ENDPROC
ENDMODULE
