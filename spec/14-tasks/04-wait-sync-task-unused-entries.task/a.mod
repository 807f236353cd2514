MODULE sync_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description WaitSyncTask with a task list whose last entries are empty strings (a list declared larger than the cell, its unused entries left ""): the empty entries name no task and are passed over (R-14-f-empty); the two tasks meet.
! @output B arrives
! @output A arrives
! @output A goes
! @output B goes
  VAR syncident meet;
  PERS tasks cell{4} := [["T_ROB1"], ["T_B"], [""], [""]];
  PROC main()
    WaitTime 1;
    TPWrite "A arrives";
    WaitSyncTask meet, cell;
    TPWrite "A goes";
  ENDPROC
ENDMODULE
