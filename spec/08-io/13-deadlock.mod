MODULE deadlock
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description A wait that nothing can ever end (no stimulus event left that could change the input, no interrupt to come) ends the run as a deadlock, exit status 3, after the clock has moved through every event.
! @output waiting
! @exit 3
  PROC main()
    TPWrite "waiting";
    WaitDI di2, 0;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
