MODULE max_time_busy
! @format 3
! @section 13
! @section 4.19
! @expect ok
! @statement-time 0.01
! @max-time 1
! @description A loop that never waits still moves the virtual clock (the statement time): beyond @max-time the run ends, exit status 3, whatever the step limit.
! @output looping
! @exit 3
  VAR num n := 0;
  PROC main()
    TPWrite "looping";
    WHILE TRUE DO
      n := n + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
