MODULE installed_routine_not_modelled
! @format 3
! @section 13
! @expect ok
! @description EGMStreamStop is installed (its signature is in the installed environment) but rapid-sem does not model position streaming of Externally Guided Motion: the run ends as unsupported, exit status 4 (doc/semantics.md).
! @output before
! @exit 4
  VAR egmident egm1;
  PROC main()
    TPWrite "before";
    EGMStreamStop egm1;
    TPWrite "after";
  ENDPROC
ENDMODULE
