MODULE reference_argument_non_value
! @format 2
! @section 2.16
! @section 11
! @expect semantic-error 10:16
! @description Table of section 2.16, row argument, column non-value: only to var or ref parameters; IsVar's parameter is inout, so refused at the argument.
  VAR iodev logfile;
  VAR bool b;
  PROC main()
    b := IsVar(logfile);
  ENDPROC
ENDMODULE
