MODULE t
! @expect-message 10:3: syntax error: expected a statement or ENDIF after the ELSE part (§4.16); found ENDPROC
! @expect-hint the IF at line 5 is not closed: the ELSE IF at line 7 opened a new IF, closed by the first ENDIF; write ELSEIF for another condition of the same IF (§4.16)
  PROC main()
    IF a THEN
      x := 1;
    ELSE IF b THEN
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
