MODULE if_statement_two_else
! @section 4.16
! @expect syntax-error 12:5
! @description An IF statement has at most one ELSE clause.
  VAR num x;
  VAR bool b;
  PROC main()
    IF b THEN
      x := 1;
    ELSE
      x := 2;
    ELSE
      x := 3;
    ENDIF
  ENDPROC
ENDMODULE
