MODULE for_statement_empty_step
! @section 4.18
! @expect syntax-error 6:29
! @description STEP is followed by an expression.
  PROC main()
    FOR i FROM 1 TO 10 STEP DO
    ENDFOR
  ENDPROC
ENDMODULE
