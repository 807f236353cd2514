MODULE t
! @expect-message 5:17: syntax error: expected ',' before the next argument, or ';' to end the procedure call (§4.6); found DO
! @expect-hint WHLIE is not a reserved word of RAPID (§2.4): did you mean WHILE?
  PROC main()
    WHLIE a > 1 DO
      a := a - 1;
    ENDWHILE
  ENDPROC
ENDMODULE
