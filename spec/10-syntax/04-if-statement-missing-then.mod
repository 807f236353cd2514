MODULE if_statement_missing_then
! @section 4.16
! @section 4.17
! @expect syntax-error 10:5
! @description Without THEN, "IF b x := 1;" is a complete compact IF statement, so the ENDIF that follows is out of place.
  VAR num x;
  VAR bool b;
  PROC main()
    IF b x := 1;
    ENDIF
  ENDPROC
ENDMODULE
