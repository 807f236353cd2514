MODULE trap_declaration_backward
! @section 5.6
! @section 6.2
! @expect syntax-error 7:3
! @description Only procedures have a BACKWARD part.
  TRAP t
  BACKWARD
  ENDTRAP
ENDMODULE
