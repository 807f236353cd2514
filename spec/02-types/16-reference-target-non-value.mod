MODULE reference_target_non_value
! @format 2
! @section 2.16
! @section 4.5
! @expect semantic-error 9:5
! @description Table of section 2.16, row target of an assignment, column non-value: illegal; refused at the target (the right-hand side is a placeholder).
  VAR iodev logfile;
  PROC main()
    logfile := <EXP>;
  ENDPROC
ENDMODULE
