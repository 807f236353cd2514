MODULE t
! @expect-message 4:15: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found a comment
  PROC main()
    TEST mode ! which mode
    CASE 1:
    ENDTEST
  ENDPROC
ENDMODULE
