MODULE t
! @expect-message 5:10: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found '|'
! @expect-hint 'or' is written OR (§3.1)
  PROC main()
    IF a || b THEN
      a := 1;
    ENDIF
  ENDPROC
ENDMODULE
