MODULE t
! @expect-message 7:5: syntax error: expected a statement or ENDFOR (§4.18); found ENDWHILE
! @expect-hint ENDWHILE closes no open construct here; the FOR at line 5 is closed by ENDFOR (§4.18)
  PROC main()
    FOR i FROM 1 TO 10 DO
      x := i;
    ENDWHILE
  ENDPROC
ENDMODULE
