MODULE t
! @expect-message 7:17: syntax error: expected ',' before the next argument, or ';' to end the procedure call (§4.6); found THEN
! @expect-hint ELSIF is not a reserved word of RAPID (§2.4): did you mean ELSEIF?
  PROC main()
    IF a > 1 THEN
      a := 1;
    ELSIF a > 2 THEN
      a := 3;
    ENDIF
  ENDPROC
ENDMODULE
