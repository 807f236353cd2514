MODULE variable_declaration_equals
! @section 2.22
! @expect syntax-error 5:13
! @description A variable is initialised with ':=', not '='.
  VAR num x = 1;
ENDMODULE
