MODULE t
! @expect-message 9:3: syntax error: expected a statement or ENDIF after the ELSE part (§4.16); found ENDPROC
  PROC main()
    IF a THEN
      x := 1;
    ELSE IF b THEN
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
