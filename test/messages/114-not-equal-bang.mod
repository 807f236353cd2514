MODULE t
! @expect-message 5:10: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found a comment
! @expect-hint '!' begins a comment (§2.10): 'not equal' is written <> (§3.1)
  PROC main()
    IF a != 1 THEN
      a := 1;
    ENDIF
  ENDPROC
ENDMODULE
