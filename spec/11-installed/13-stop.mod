MODULE stop_use
! @format 3
! @section 13
! @expect ok
! @description Stop stops program execution (installed-facts.md section 4); nothing restarts it in a run, so the run ends there without error: exit 0, nothing after Stop is written (reading: a stopped run is not an error stop).
! @output before
! @exit 0
  PROC main()
    TPWrite "before";
    Stop;
    TPWrite "after";
  ENDPROC
ENDMODULE
