MODULE max_time
! @format 3
! @section 13
! @expect ok
! @max-time 10
! @description Virtual time is bounded (@max-time, --max-time): a wait beyond the bound ends the run, exit status 3, without waiting in host time.
! @output waiting
! @exit 3
  PROC main()
    TPWrite "waiting";
    WaitTime 3600;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
