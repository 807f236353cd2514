MODULE t
! @expect-message 6:11: syntax error: expected a simple expression after the comparison operator (§3.1); NOT may only begin an expression: write (NOT ...); comments are list elements only (§2.10); found '='
! @expect-hint RAPID compares with a single '=' (§3.1): write a = b, not a == b; an assignment is written ':=' (§4.5)
  PROC main()
    VAR num a;
    IF a == 1 THEN
      a := 2;
    ENDIF
  ENDPROC
ENDMODULE
