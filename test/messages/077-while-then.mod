MODULE t
! @expect-message 5:18: syntax error: expected DO after the WHILE condition (§4.19); found THEN
! @expect-hint the WHILE at line 5 takes DO after its condition, not THEN (§4.19)
  PROC main()
    WHILE x < 10 THEN
    ENDWHILE
  ENDPROC
ENDMODULE
