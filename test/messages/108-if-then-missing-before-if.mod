MODULE t
! @expect-message 6:7: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found IF
! @expect-hint the IF at line 5 has no THEN after its condition (§4.16)
  PROC main()
    IF a > 1
      IF b THEN
        x := 1;
      ENDIF
    ENDIF
  ENDPROC
ENDMODULE
