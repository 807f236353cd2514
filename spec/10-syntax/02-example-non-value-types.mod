MODULE example_non_value_types
! @section 2.16
! @expect ok
! @description The non-value and semi-value examples of section 2.16, elisions completed.
  VAR iodev logfile;
  VAR signaldi sig1;
  VAR num x;
  PROC main()
    ! Open logfile
    Open "flp1:LOGDIR" \File := "LOGFILE1.DOC ", logfile;
    ! Write timestamp to logfile
    Write logfile, "timestamp = " + GetTime();
    ! use digital input sig1 as value object
    IF sig1 = 1 THEN
      x := 1;
    ENDIF
    ! use digital input sig1 as non-value object
    IF DInput(sig1) = 1 THEN
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE
