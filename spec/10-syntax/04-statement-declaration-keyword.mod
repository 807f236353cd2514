MODULE statement_declaration_keyword
! @section 4.1
! @expect syntax-error 8:5
! @description A data declaration does not follow a statement: the data declaration list comes first.
  VAR num x;
  PROC main()
    x := 1;
    PERS num y := 0;
  ENDPROC
ENDMODULE
