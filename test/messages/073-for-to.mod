MODULE t
! @expect-message 4:18: syntax error: expected TO after the FROM expression (§4.18); found DO
  PROC main()
    FOR i FROM 1 DO
    ENDFOR
  ENDPROC
ENDMODULE
