MODULE clock_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description The tasks wait on one virtual clock: while one waits the others run, and when all wait the clock moves to the earliest end of a wait (R-14-a). B's WaitTime 1 ends before A's WaitTime 2.
! @output B after 1 s
! @output A after 2 s
  PROC main()
    WaitTime 2;
    TPWrite "A after 2 s";
  ENDPROC
ENDMODULE
