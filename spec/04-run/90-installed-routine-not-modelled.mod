MODULE installed_routine_not_modelled
! @format 3
! @section 13
! @expect ok
! @description MoveExtJ is installed (its signature is in the installed environment) but rapid-sem does not model external axes (doc/motion.md): the run ends as unsupported, exit status 4 (doc/semantics.md).
! @output before
! @exit 4
  CONST jointtarget j1 := [[9E9,9E9,9E9,9E9,9E9,9E9],[90,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "before";
    MoveExtJ j1, vrot50, fine;
    TPWrite "after";
  ENDPROC
ENDMODULE
