MODULE while_statement_wrong_end
! @section 4.19
! @expect syntax-error 9:5
! @description A WHILE statement is closed by ENDWHILE.
  VAR num a;
  VAR num b;
  PROC main()
    WHILE a < b DO
    ENDFOR
  ENDPROC
ENDMODULE
