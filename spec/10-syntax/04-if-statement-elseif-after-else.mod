MODULE if_statement_elseif_after_else
! @section 4.16
! @expect syntax-error 12:5
! @description ELSEIF clauses come before the ELSE clause.
  VAR num x;
  VAR bool b;
  PROC main()
    IF b THEN
      x := 1;
    ELSE
      x := 2;
    ELSEIF b THEN
      x := 3;
    ENDIF
  ENDPROC
ENDMODULE
