MODULE routine_data_hides_module_data
! @format 2
! @section 2.20
! @expect ok
! @description A routine data object hides a module object of the same name: level is a num inside main.
  VAR string level;
  PROC main()
    VAR num level;
    level := 3;
  ENDPROC
ENDMODULE
