MODULE data_declaration_statement_at_mo
! @section 2.18
! @section 9.2
! @section 4.1
! @expect syntax-error 8:3
! @description A module holds declarations, not statements: the identifier x cannot begin a module-level item (only TASK could).
  VAR num x;
  x := 1;
ENDMODULE
