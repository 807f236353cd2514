MODULE t
! @expect-message 4:9: syntax error: expected ':=' after the assignment target (§4.5); found the numeric literal 5
  PROC main()
    p.x 5;
  ENDPROC
ENDMODULE
