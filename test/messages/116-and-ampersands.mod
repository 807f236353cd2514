MODULE t
! @expect-message 5:10: lexical error: illegal character '&' (§2.1)
! @expect-hint 'and' is written AND (§3.1); strings are joined with + (§3.12)
  PROC main()
    IF a && b THEN
      a := 1;
    ENDIF
  ENDPROC
ENDMODULE
