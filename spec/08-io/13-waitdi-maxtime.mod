MODULE waitdi_maxtime
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description WaitDI \MaxTime without \TimeFlag: when the time runs out, ERR_WAIT_MAXTIME is raised at the WaitDI (installed-facts.md section 4); nothing handles it here, so the system error handler stops the task.
! @output waiting
! @exit 1
! @error ERR_WAIT_MAXTIME 13:5
  PROC main()
    TPWrite "waiting";
    WaitDI di2, 0 \MaxTime:=0.5;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
