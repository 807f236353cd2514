MODULE for_statement_missing_from
! @section 4.18
! @section 1.4
! @expect syntax-error 7:11
! @description The example of a syntax error in section 1.4: FOR i 5 TO 10 DO lacks FROM.
  PROC main()
    FOR i 5 TO 10 DO
    ENDFOR
  ENDPROC
ENDMODULE
