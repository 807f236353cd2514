MODULE parameter_hides_module_data
! @format 2
! @section 5.3
! @section 2.20
! @expect ok
! @description A parameter hides a module object of the same name.
  VAR string level;
  PROC set_level(num level)
    level := level + 1;
  ENDPROC
ENDMODULE
