MODULE late_local_hidden
! @format 3
! @section 4.6
! @section 5.3
! @section 12
! @expect ok
! @description A plain late-bound name follows the scope rules: a LOCAL procedure of another module is not visible (section 5.3), so "secret" is unknown here: ERR_REFUNKPRC.
! @exit 1
! @error ERR_REFUNKPRC a.mod:11:5
  PROC main()
    % "secret" %;
  ENDPROC
ENDMODULE
