MODULE procedure_declaration_no_parenth
! @section 5.4
! @expect syntax-error 6:5
! @description PROC <procedure name> '(' [ <parameter list> ] ')': the parentheses may not be left out.
  PROC main
    x := 1;
  ENDPROC
ENDMODULE
