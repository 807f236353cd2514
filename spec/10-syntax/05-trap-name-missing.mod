MODULE trap_name_missing
! @section 5.6
! @expect syntax-error 6:5
! @description TRAP <trap name>: the name may not be left out.
  TRAP
    RETURN;
  ENDTRAP
ENDMODULE
