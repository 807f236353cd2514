MODULE if_statement_missing_endif
! @section 4.16
! @expect syntax-error 10:5
! @description An IF statement is closed by ENDIF.
  VAR num x;
  VAR bool b;
  PROC main()
    IF b THEN
      x := 1;
    ENDPROC
  ENDPROC
ENDMODULE
