MODULE t
! @expect-message 7:3: syntax error: expected a statement or ENDWHILE (§4.19); found ENDPROC
! @expect-hint the WHILE at line 5 is not closed: ENDWHILE is missing before this ENDPROC (§4.19)
  PROC main()
    WHILE a > 1 DO
      a := a - 1;
  ENDPROC
ENDMODULE
