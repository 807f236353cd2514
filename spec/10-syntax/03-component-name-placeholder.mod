MODULE component_name_placeholder
! @section 3.6
! @expect syntax-error 7:7
! @description <component name> ::= <ident>: <ID> cannot stand for it.
  VAR pos p;
  PROC main()
    p.<ID> := 1;
  ENDPROC
ENDMODULE
