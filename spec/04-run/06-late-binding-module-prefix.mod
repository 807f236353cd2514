MODULE late_binding_module_prefix
! @format 3
! @section 4.6
! @expect ok
! @description "name1:name2" names procedure name2 declared in module name1 (section 4.6), here the case's own module, local procedure included.
! @output local one
! @output global one
! @exit 0
  LOCAL PROC one()
    TPWrite "local one";
  ENDPROC
  PROC two()
    TPWrite "global one";
  ENDPROC
  PROC main()
    % "late_binding_module_prefix:one" %;
    % "late_binding_module_prefix:two" %;
  ENDPROC
ENDMODULE
