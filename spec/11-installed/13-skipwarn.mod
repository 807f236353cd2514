MODULE skipwarn_use
! @format 3
! @section 7.5
! @section 13
! @expect ok
! @description SkipWarn only keeps the latest warning out of the event log (section 7.5); in an error handler before RETRY it changes nothing else (section 7.5's pattern, with a flag instead of a busy file).
! @output busy
! @output written
! @exit 0
  VAR bool busy := TRUE;
  PROC write_report()
    IF busy RAISE 50;
    TPWrite "written";
  ENDPROC
  PROC main()
    write_report;
  ERROR
    IF ERRNO = 50 THEN
      TPWrite "busy";
      busy := FALSE;
      SkipWarn;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
