MODULE app
! @format 2
! @section 9.3
! @section 9.1
! @expect ok
! @description A system module (.sys, SYSMODULE) in the task buffer provides global data and routines to a task module, like section 9.3's sysun1.
  PROC main()
    n1 := n1 + 1;
    p1 := p2;
    p1.z := n1;
    log_value n1;
  ENDPROC
ENDMODULE
