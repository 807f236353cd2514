MODULE for_statement_wrong_end
! @section 4.18
! @expect syntax-error 7:5
! @description A FOR statement is closed by ENDFOR.
  PROC main()
    FOR i FROM 1 TO 10 DO
    ENDWHILE
  ENDPROC
ENDMODULE
