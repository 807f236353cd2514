MODULE signal_writer
! @format 4
! @task T_ROB1
! @section 14
! @section 13
! @options allow-unknown
! @options stub-unmodelled
! @expect ok
! @description ch. 14 and doc/rulings.md R-13-aa: under --allow-unknown --stub-unmodelled an undeclared name passed as a signal is a virtual signal of the controller, one for every task: the other task waits for the output this task sets, and sees it.
! @output B saw 1
  PROC main()
    WaitTime 0.1;
    SetDO doReady, 1;
  ENDPROC
ENDMODULE
