MODULE example_persistent_module
! @section 2.23
! @expect ok
! @description The module of section 2.23 before it is saved; its elided name and routine completed.
  PERS pos refpnt := [0, 0, 0];
  VAR num x;
  VAR num y;
  VAR num z;
  PROC main()
    refpnt := [x, y, z];
  ENDPROC
ENDMODULE
