MODULE t
! @expect-message 6:7: syntax error: expected STEP or DO after the TO expression (§4.18); found the identifier x
! @expect-hint the FOR at line 5 has no DO after its range (§4.18)
  PROC main()
    FOR i FROM 1 TO 10
      x := i;
    ENDFOR
  ENDPROC
ENDMODULE
