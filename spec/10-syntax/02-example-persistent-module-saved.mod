MODULE example_persistent_module_saved
! @section 2.23
! @expect ok
! @description The module of section 2.23 as saved after execution.
  PERS pos refpnt := [100.23, 778.55, 1183.98];
  VAR num x;
  VAR num y;
  VAR num z;
  PROC main()
    refpnt := [x, y, z];
  ENDPROC
ENDMODULE
