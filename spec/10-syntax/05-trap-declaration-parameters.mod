MODULE trap_declaration_parameters
! @section 5.6
! @expect syntax-error 5:9
! @description A trap declaration has no parameter list.
  TRAP t()
  ENDTRAP
ENDMODULE
