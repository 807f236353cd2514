MODULE sync_timeout_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @expect ok
! @description WaitSyncTask \TimeOut: the other task does not arrive in time, ERR_WAITSYNCTASK is raised and handled; a task name that is not installed is ERR_TASKNAME.
! @output timed out after 1 s
! @output ERR_TASKNAME
  VAR syncident meet;
  VAR syncident other;
  PERS tasks both{2} := [["T_ROB1"], ["T_B"]];
  PERS tasks wrong{2} := [["T_ROB1"], ["T_NONE"]];
  PROC main()
    WaitSyncTask meet, both \TimeOut := 1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WAITSYNCTASK THEN
      TPWrite "timed out after 1 s";
      try_wrong;
      RETURN;
    ENDIF
  ENDPROC
  PROC try_wrong()
    WaitSyncTask other, wrong;
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "ERR_TASKNAME";
    RETURN;
  ENDPROC
ENDMODULE
