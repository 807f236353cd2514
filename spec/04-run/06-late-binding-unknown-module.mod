MODULE late_binding_unknown_module
! @format 3
! @section 4.6
! @section 12
! @expect ok
! @description "name1:name2" names procedure name2 of module name1 (section 4.6); when no module name1 exists the procedure is unknown: ERR_REFUNKPRC.
! @exit 1
! @error ERR_REFUNKPRC 13:5
  PROC show()
    TPWrite "shown";
  ENDPROC
  PROC main()
    % "no_module:show" %;
  ENDPROC
ENDMODULE
