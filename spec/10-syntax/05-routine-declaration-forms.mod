MODULE routine_declaration_forms
! @section 5.1
! @expect ok
! @description <routine declaration> ::= [LOCAL] (<procedure declaration> | <function declaration> | <trap declaration>) | <comment> | <RDN>.
  PROC p1()
  ENDPROC
  LOCAL PROC p2()
  ENDPROC
  FUNC num f1()
    RETURN 1;
  ENDFUNC
  LOCAL FUNC num f2()
    RETURN 2;
  ENDFUNC
  TRAP t1
  ENDTRAP
  LOCAL TRAP t2
  ENDTRAP
  ! a comment
  <RDN>
ENDMODULE
