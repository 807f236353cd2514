MODULE t
! @expect-message 8:3: syntax error: expected ':=' for an assignment, ':' for a label, or the arguments or ';' of a procedure call (§4.4, §4.5, §4.6); found ENDPROC
! @expect-hint ENDFI is not a reserved word of RAPID (§2.4): did you mean ENDIF?
  PROC main()
    IF a > 1 THEN
      a := 1;
    ENDFI
  ENDPROC
ENDMODULE
