MODULE one_task
! @format 3
! @section 14
! @expect ok
! @description A run of one task: GetTaskName gives T_ROB1, task 1, which is the motion task too (R-14-d); WaitSyncTask with a list of that task alone meets at once, also with \TimeOut (R-14-f); a list naming a task that is not in the run raises ERR_TASKNAME, which the error handler takes.
! @output T_ROB1 1
! @output motion T_ROB1 1
! @output met
! @output met again
! @output ERR_TASKNAME
! @output end
  PERS tasks alone{1} := [["T_ROB1"]];
  PERS tasks others{2} := [["T_ROB1"],["T_ARC"]];
  VAR syncident meet;
  VAR syncident other;
  PROC main()
    VAR num n;
    VAR num m;
    TPWrite GetTaskName(\TaskNo := n) + " " + NumToStr(n, 0);
    TPWrite "motion " + GetTaskName(\MecTaskNo := m) + " " + NumToStr(m, 0);
    WaitSyncTask meet, alone;
    TPWrite "met";
    WaitSyncTask meet, alone \TimeOut := 1;
    TPWrite "met again";
    WaitSyncTask other, others;
    TPWrite "end";
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "ERR_TASKNAME";
    TRYNEXT;
  ENDPROC
ENDMODULE
