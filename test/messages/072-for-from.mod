MODULE t
! @expect-message 4:11: syntax error: expected FROM after the loop variable (§4.18); found the numeric literal 5
  PROC main()
    FOR i 5 TO 10 DO
    ENDFOR
  ENDPROC
ENDMODULE
