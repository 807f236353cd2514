MODULE reference_connect_target_non
! @format 2
! @section 2.16
! @section 4.15
! @expect semantic-error 9:13
! @description Table of section 2.16, row target of a connect statement, column non-value: illegal; refused at the target.
  VAR iodev logfile;
  PROC main()
    CONNECT logfile WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
