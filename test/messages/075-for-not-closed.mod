MODULE t
! @expect-message 6:5: syntax error: expected a statement or ENDFOR (§4.18); found ENDWHILE
  PROC main()
    FOR i FROM 1 TO 10 DO
      x := i;
    ENDWHILE
  ENDPROC
ENDMODULE
