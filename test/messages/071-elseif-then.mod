MODULE t
! @expect-message 6:7: syntax error: expected THEN after the ELSEIF condition (§4.16); found the identifier x
  PROC main()
    IF a THEN
    ELSEIF b
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
