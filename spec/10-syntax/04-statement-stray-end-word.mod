MODULE statement_stray_end_word
! @section 4.1
! @expect syntax-error 8:5
! @description ENDIF closes an IF statement; it is not a statement.
  VAR num x;
  PROC main()
    x := 1;
    ENDIF
  ENDPROC
ENDMODULE
