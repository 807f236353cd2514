MODULE t
! @expect-message 5:7: syntax error: expected STEP or DO after the TO expression (§4.18); found the identifier x
  PROC main()
    FOR i FROM 1 TO 10
      x := i;
    ENDFOR
  ENDPROC
ENDMODULE
