MODULE while_statement_missing_do
! @section 4.19
! @expect syntax-error 8:17
! @description WHILE <conditional expression> DO: DO may not be left out.
  VAR num a;
  VAR num b;
  PROC main()
    WHILE a < b a := a + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
