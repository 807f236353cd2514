MODULE installed_routine_not_modelled
! @format 3
! @section 13
! @expect ok
! @description MoveL is installed (its signature is in the installed environment) but rapid-sem does not model motion yet: the run ends as unsupported, exit status 4 (doc/semantics.md).
! @output before
! @exit 4
  CONST robtarget p1 := [[600,0,800],[1,0,0,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  PROC main()
    TPWrite "before";
    MoveL p1, v100, fine, tool0;
    TPWrite "after";
  ENDPROC
ENDMODULE
