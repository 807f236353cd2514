MODULE egm_not_modelled
! @format 3
! @section 13
! @expect ok
! @description Pose-mode EGM is not modelled (doc/rulings.md R-13-egm1): EGMSetupUC \Pose ends the run at the call as an installed routine rapid-sem does not model (exit 4), after what came before it ran.
! @output before
! @exit 4
! @error EGMSetupUC 13:5
  VAR egmident id;
  PROC main()
    EGMGetId id;
    TPWrite "before";
    EGMSetupUC ROB_1, id, "default", "EGMSensor" \Pose;
  ENDPROC
ENDMODULE
