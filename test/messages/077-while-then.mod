MODULE t
! @expect-message 4:18: syntax error: expected DO after the WHILE condition (§4.19); found THEN
  PROC main()
    WHILE x < 10 THEN
    ENDWHILE
  ENDPROC
ENDMODULE
